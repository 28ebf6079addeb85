"""Loading libsample's shared libraries and declaring their C API to ctypes.

The structures below mirror libsample/include/sample/sample.h and
libsample/io/include/sample/sample_io.h field for field (C enums are ints);
tests/python.cmake runs the package against the libraries it was built with,
and a layout mismatch shows up there as wrong results.

Where the libraries are looked for, in this order (doc/python.md):

1. the directories in the environment variable ``LIBSAMPLE_LIBRARY_PATH``
   (separated by ``os.pathsep``);
2. the install tree: ``_install_paths.py``, written by ``cmake --install``
   beside this file, names the library directory relative to the package;
3. the build tree of a source checkout (``build/`` beside ``python/``);
4. the dynamic loader's own search (``LD_LIBRARY_PATH``, ld.so.cache).

ctypes calls C functions with the GIL released (CDLL, not PyDLL), so
sampling runs in parallel with other Python threads.
"""
import ctypes
import os

_HERE = os.path.dirname(os.path.abspath(__file__))

# Library file names: the SONAME first (what an install holds), then the
# development link name (what a build tree also has).
_NAMES = {
    "sample": ("libsample.so.0", "libsample.so"),
    "sample_io": ("libsample_io.so.0", "libsample_io.so"),
    "sample_measure": ("libsample_measure.so",),
}
# Where a build tree keeps each library, relative to the build directory.
_BUILD_SUBDIRS = {"sample": "libsample", "sample_io": "libsample/io", "sample_measure": "tools"}


def _search_dirs(lib):
    dirs = []
    env = os.environ.get("LIBSAMPLE_LIBRARY_PATH")
    if env:
        dirs += [d for d in env.split(os.pathsep) if d]
    try:
        from . import _install_paths  # written by cmake --install only

        dirs.append(os.path.normpath(os.path.join(_HERE, _install_paths.LIBDIR)))
    except ImportError:
        pass
    dirs.append(os.path.normpath(os.path.join(_HERE, "..", "..", "build", _BUILD_SUBDIRS[lib])))
    return dirs


def load(lib):
    """Load libsample's shared library `lib` ("sample", "sample_io",
    "sample_measure"), or raise ImportError saying where it looked."""
    tried = []
    for d in _search_dirs(lib):
        for name in _NAMES[lib]:
            path = os.path.join(d, name)
            if os.path.exists(path):
                return ctypes.CDLL(path)
            tried.append(path)
    for name in _NAMES[lib]:
        try:
            return ctypes.CDLL(name)
        except OSError:
            tried.append(name + " (dynamic loader)")
    raise ImportError(
        "libsample: cannot find lib%s; looked in:\n  %s\n"
        "Build it (cmake --build build --target %s_shared) or set LIBSAMPLE_LIBRARY_PATH "
        "to the directory that holds it." % (lib, "\n  ".join(tried), lib))


# ---- sample.h ---------------------------------------------------------------

c_float_p = ctypes.POINTER(ctypes.c_float)


class Error(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("message", ctypes.c_char * 256)]


class Image(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("channels", ctypes.c_int),
                ("format", ctypes.c_int), ("data", ctypes.c_void_p), ("row_stride", ctypes.c_size_t)]


class MipParams(ctypes.Structure):
    _fields_ = [("filter", ctypes.c_int), ("wrap_s", ctypes.c_int), ("wrap_t", ctypes.c_int),
                ("max_levels", ctypes.c_int), ("wrap_r", ctypes.c_int)]


class TextureInfo(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("channels", ctypes.c_int),
                ("levels", ctypes.c_int), ("format", ctypes.c_int), ("bytes", ctypes.c_size_t),
                ("kind", ctypes.c_int), ("depth", ctypes.c_int)]


class SamplerState(ctypes.Structure):
    _fields_ = [("wrap_s", ctypes.c_int), ("wrap_t", ctypes.c_int), ("wrap_r", ctypes.c_int),
                ("min_filter", ctypes.c_int), ("mag_filter", ctypes.c_int),
                ("border_color", ctypes.c_float * 4), ("lod_bias", ctypes.c_float),
                ("min_lod", ctypes.c_float), ("max_lod", ctypes.c_float),
                ("base_level", ctypes.c_int), ("max_level", ctypes.c_int),
                ("max_anisotropy", ctypes.c_float), ("max_lod_bias", ctypes.c_float),
                ("footprint", ctypes.c_int), ("cubic", ctypes.c_int), ("options", ctypes.c_uint),
                ("ewa_kernel", ctypes.c_int)]


class Query(ctypes.Structure):
    _fields_ = [(n, ctypes.c_float) for n in ("s", "t", "dsdx", "dtdx", "dsdy", "dtdy")]


class BatchArgs(ctypes.Structure):
    _fields_ = [("count", ctypes.c_size_t), ("queries", ctypes.c_void_p), ("corners", ctypes.c_void_p),
                ("lod_bias", ctypes.c_void_p), ("rgba", ctypes.c_void_p), ("drgba_ds", ctypes.c_void_p),
                ("drgba_dt", ctypes.c_void_p), ("stats", ctypes.c_void_p), ("u", ctypes.c_void_p),
                ("draws", ctypes.c_uint)]


class Volume(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("depth", ctypes.c_int),
                ("channels", ctypes.c_int), ("format", ctypes.c_int), ("data", ctypes.c_void_p),
                ("row_stride", ctypes.c_size_t), ("slice_stride", ctypes.c_size_t)]


class Batch3Args(ctypes.Structure):
    _fields_ = [("count", ctypes.c_size_t), ("queries", ctypes.c_void_p), ("lod_bias", ctypes.c_void_p),
                ("rgba", ctypes.c_void_p), ("stats", ctypes.c_void_p)]


def _declare(lib, name, restype, *argtypes):
    f = getattr(lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)


P = ctypes.POINTER
core = load("sample")
for _n, _r, _a in [
    ("sample_strerror", ctypes.c_char_p, [ctypes.c_int]),
    ("sample_format_bytes", ctypes.c_size_t, [ctypes.c_int]),
    ("sample_mip_params_init", None, [P(MipParams)]),
    ("sample_texture_create", ctypes.c_int, [P(Image), P(MipParams), P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_create_levels", ctypes.c_int, [P(Image), ctypes.c_int, P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_destroy", None, [ctypes.c_void_p]),
    ("sample_texture_info_get", None, [ctypes.c_void_p, P(TextureInfo)]),
    ("sample_texture_level_size", ctypes.c_int, [ctypes.c_void_p, ctypes.c_int, P(ctypes.c_int), P(ctypes.c_int)]),
    ("sample_texture_texel", None, [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, c_float_p]),
    ("sample_sampler_init", None, [P(SamplerState)]),
    ("sample_sampler_validate", ctypes.c_int, [P(SamplerState)]),
    ("sample_batch", ctypes.c_int, [ctypes.c_void_p, P(SamplerState), P(BatchArgs)]),
    ("sample_isa_name", ctypes.c_char_p, []),
    ("sample_texture_create_cube", ctypes.c_int, [P(Image), P(MipParams), P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_create_cube_levels", ctypes.c_int, [P(Image), ctypes.c_int, P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_create_3d", ctypes.c_int, [P(Volume), P(MipParams), P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_create_3d_levels", ctypes.c_int, [P(Volume), ctypes.c_int, P(ctypes.c_void_p), P(Error)]),
    ("sample_texture_level_size3", ctypes.c_int,
     [ctypes.c_void_p, ctypes.c_int, P(ctypes.c_int), P(ctypes.c_int), P(ctypes.c_int)]),
    ("sample_texture_texel_layer", None,
     [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int, c_float_p]),
    ("sample_batch_cube", ctypes.c_int, [ctypes.c_void_p, P(SamplerState), P(Batch3Args)]),
    ("sample_batch_latlong", ctypes.c_int, [ctypes.c_void_p, P(SamplerState), P(Batch3Args)]),
    ("sample_batch_3d", ctypes.c_int, [ctypes.c_void_p, P(SamplerState), P(Batch3Args)]),
]:
    _declare(core, _n, _r, *_a)
for _kind in ("wrap", "filter", "cubic", "footprint", "ewa_kernel", "mipgen"):
    _declare(core, "sample_%s_name" % _kind, ctypes.c_char_p, ctypes.c_int)
    _declare(core, "sample_%s_parse" % _kind, ctypes.c_int, ctypes.c_char_p)
_declare(core, "sample_format_name", ctypes.c_char_p, ctypes.c_int)
_declare(core, "sample_texture_kind_name", ctypes.c_char_p, ctypes.c_int)

# ---- sample_io.h (optional: a build without libsample_io has none) ----------


class IoOptions(ctypes.Structure):
    _fields_ = [("colorspace", ctypes.c_char_p), ("ocio_config", ctypes.c_char_p),
                ("use_file_levels", ctypes.c_int), ("max_bytes", ctypes.c_size_t),
                ("float_storage", ctypes.c_int), ("premultiply", ctypes.c_int),
                ("file_info", ctypes.c_void_p), ("mip_wrap_from_file", ctypes.c_int)]


_io = None
_io_error = None


def io():
    """libsample_io, loaded on first use (it pulls in OpenImageIO)."""
    global _io, _io_error
    if _io is None and _io_error is None:
        try:
            lib = load("sample_io")
            _declare(lib, "sample_io_options_init", None, P(IoOptions))
            _declare(lib, "sample_io_read_texture", ctypes.c_int, ctypes.c_char_p, P(IoOptions),
                     P(MipParams), P(ctypes.c_void_p), P(Error))
            _io = lib
        except ImportError as e:
            _io_error = e
    if _io is None:
        raise _io_error
    return _io
