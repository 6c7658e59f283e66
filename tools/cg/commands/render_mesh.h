/* The rasterizer's path of `cg render`: a mesh file through the z-buffer,
 * the painter's algorithm or plain depth sort. */
#ifndef CG_TOOL_RENDER_MESH_H
#define CG_TOOL_RENDER_MESH_H

#include "render_request.h"

/* Loads r->trace.input, places the camera, renders (r->trace.common.repeat
 * times when > 0, printing "frame: 12.3 ms") and writes the output.
 * Returns the exit status after printing any error. */
int render_mesh_raster(const char *command, const render_request *r);

#endif
