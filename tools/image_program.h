/* The front program's way to the image program (tools/CMakeLists.txt,
 * doc/cli.md "Start-up"): texsample itself links libsample alone, and runs
 * texsample-image, the same commands linked with libsample_io and
 * OpenImageIO, for the commands that read or write image files. */
#ifndef TEXSAMPLE_IMAGE_PROGRAM_H
#define TEXSAMPLE_IMAGE_PROGRAM_H

/* Replace this process by texsample-image running subcommand argv[0] with
 * argv[1 .. argc-1]. Returns only on failure, with EXIT_RUNTIME after
 * reporting why (not installed, not executable). */
int image_program_run(int argc, char **argv);

#endif
