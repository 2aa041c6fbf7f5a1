/*
 * silk - smooth silhouettes for coarse meshes, in fixed point, in software.
 * One include for the whole public API.
 */
#ifndef SILK_H
#define SILK_H

#define SILK_VERSION "0.1.0"

#include "fixed.h"
#include "arena.h"
#include "error.h"
#include "mesh.h"
#include "model.h"
#include "compact.h"
#include "camera.h"
#include "raster.h"
#include "hal.h"
#include "texture.h"
#include "silmap.h"
#include "siltex.h"
#include "visibility.h"
#include "budget.h"
#include "render.h"
#include "scene.h"

#endif
