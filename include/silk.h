/*
 * silk.h - the header of the Arduino and PlatformIO packages: the core
 * (silk/silk.h), the check of a packed model (silk/validate.h) and the
 * ILI9341 / ST7789 panel sink (silk_panel.h, in platform/panel: the
 * packages put it on the include path).  A sketch includes <silk.h>; a
 * program built with the Makefile includes "silk/silk.h" and, for the
 * panel, -Iplatform/panel.
 */
#ifndef SILK_PACKAGE_H
#define SILK_PACKAGE_H

#include "silk/silk.h"
#include "silk/validate.h"
#include "silk_panel.h"

#endif
