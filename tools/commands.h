/* texsample's subcommands; each is defined in its own file. */
#ifndef TEXSAMPLE_COMMANDS_H
#define TEXSAMPLE_COMMANDS_H

int cmd_lookup(int argc, char **argv);  /* cmd_lookup.c */
int cmd_info(int argc, char **argv);    /* cmd_info.c */
int cmd_mip(int argc, char **argv);     /* cmd_mip.c */
int cmd_render(int argc, char **argv);  /* render/cmd_render.c */
int cmd_compare(int argc, char **argv); /* compare/cmd_compare.c */
int cmd_freq(int argc, char **argv);    /* freq/cmd_freq.c */
int cmd_bench(int argc, char **argv);   /* bench/cmd_bench.c */

#endif
