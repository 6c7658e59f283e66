/* Writing the path tracer's sums (cg/pathtrace.h) as a picture or a part:
 * shared by `cg render --algorithm pathtrace` and `cg merge`. */
#ifndef CG_TOOL_PATHTRACE_OUTPUT_H
#define CG_TOOL_PATHTRACE_OUTPUT_H

#include "cg/pathtrace.h"

/* Writes a whole-image part (tile = image, samples [0, spp) or fewer when a
 * time budget stopped it at sample_end) to path: .pfm as linear float RGB,
 * .part as a part file, anything else through cg_image_write after the
 * filmic tone map at the exposure (stops).  Atomic; prints the error;
 * returns an exit status. */
int pathtrace_write(const char *command, const cg_path_part *whole, const char *path,
                    double exposure);

/* True when path ends in ".part". */
int pathtrace_is_part(const char *path);

#endif
