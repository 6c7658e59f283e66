/* Private pieces shared by the colour sources. */
#ifndef CG_COLOR_INTERNAL_H
#define CG_COLOR_INTERNAL_H

/* The D65 white of the sRGB matrix: its row sums, written as sums so that
 * they equal (bit for bit) the matrix applied to linear white. */
#define CG_COLOR_WHITE_X (0.4124 + 0.3576 + 0.1805)
#define CG_COLOR_WHITE_Z (0.0193 + 0.1192 + 0.9505)

#endif
