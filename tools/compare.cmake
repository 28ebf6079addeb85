# texsample compare writes its PNGs itself (tools/compare/png.c) so that it
# needs no image library; zlib does the deflate.
find_package(ZLIB REQUIRED)
target_link_libraries(texsample PRIVATE ZLIB::ZLIB m)
