/* Composes a rotation about an axis with a translation and applies it to the
 * corners of a unit square, then prints where they land. */
#include <cg.h>
#include <stdio.h>

int main(void)
{
    cg_mat4 rotate;
    if (cg_xform3_rotate_axis(cg_vec3_make(0, 0, 1), CG_PI / 2, cg_vec3_make(0, 0, 0), &rotate)
        != CG_OK)
        return 1;
    cg_mat4 steps[2] = {rotate, cg_xform3_translate(10, 0, 0)};
    cg_mat4 both = cg_mat4_compose(steps, 2); /* rotate first, then translate */
    cg_vec3 square[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    cg_mat4_transform_points(both, square, square, 4);
    for (int i = 0; i < 4; i++)
        printf("%g %g %g\n", square[i].x, square[i].y, square[i].z);
    return 0;
}
