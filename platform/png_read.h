/*
 * png_read.h - silk_png_read(), the PNG reader of the host tools; declared
 * in the public header silk/platform.h.
 */
#ifndef SILK_PNG_READ_H
#define SILK_PNG_READ_H

#include "silk/platform.h"

#endif
