/* Private pieces shared by the clip module's files. */
#ifndef CG_CLIP_INTERNAL_H
#define CG_CLIP_INTERNAL_H

#include "cg/clip.h"

__extension__ typedef __int128 clip_i128;

#endif
