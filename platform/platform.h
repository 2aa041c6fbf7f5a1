/*
 * platform.h - the host-side I/O of the tool and tests: file reading, atomic
 * output, the image writers and readers.  Declared in the public header
 * silk/platform.h, which `make install` installs with libsilk_platform.a.
 */
#ifndef SILK_PLATFORM_INTERNAL_H
#define SILK_PLATFORM_INTERNAL_H

#include "silk/platform.h"

#endif
