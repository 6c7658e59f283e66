/* Private: constant tables of the 8-bit colour fast paths (tables.c). */
#ifndef CG_COLOR_TABLES_H
#define CG_COLOR_TABLES_H

#include <stdint.h>

#define CG_LAB_F_SIZE 4096
extern const uint32_t cg_color_reciprocal[3061];
extern const float cg_lab_f_table[CG_LAB_F_SIZE + 2];
extern const float cg_lab_channel_table[3][256][3];

#endif
