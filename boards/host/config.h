/*
 * boards/host/config.h - the core's build options for a host (a Linux or
 * macOS desktop; include/silk/config.h says what each does): the defaults,
 * every mode and feature built in and every shortcut taken.  The Makefile
 * names it in -DSILK_CONFIG_FILE for `make` (BOARD=host), and for the
 * host-side tool of the firmware boards, which packs their models.
 */
