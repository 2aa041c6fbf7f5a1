/*
 * boards/linux-fb/config.h - the core's build options for a Linux machine
 * with a framebuffer (include/silk/config.h says what each does): the
 * defaults, as on a host.  A small Linux board short of RAM or flash could
 * leave out what boards/mps2-an385/config.h leaves out.
 */
