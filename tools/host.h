/*
 * host.h - what every part of the silk command shares (the command line,
 * preparation, the viewer, the image helpers): the one pi and degrees to
 * radians.  Host code: double precision.
 */
#ifndef SILK_TOOLS_HOST_H
#define SILK_TOOLS_HOST_H

#define HOST_PI 3.14159265358979323846
#define HOST_DEG (HOST_PI / 180)

#endif
