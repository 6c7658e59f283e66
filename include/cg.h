/* cg.h - the whole public API of libcg. */
#ifndef CG_H
#define CG_H

#include "cg/core.h"
#include "cg/image.h"
#include "cg/image_float.h"
#include "cg/color.h"
#include "cg/light.h"
#include "cg/xform.h"
#include "cg/draw.h"
#include "cg/curve.h"
#include "cg/fill.h"
#include "cg/texture.h"
#include "cg/svg.h"
#include "cg/text.h"
#include "cg/mesh.h"
#include "cg/clip.h"
#include "cg/polygon.h"
#include "cg/hemesh.h"
#include "cg/render.h"
#include "cg/scene.h"
#include "cg/trace.h"
#include "cg/pathtrace.h"
#include "cg/trace_steps.h"

#endif
