/* Gallery: shading (chapter 8) - defined with the pipeline pictures. */
#include "demo.h"

int demo_render_shading(demo_context *context);

const demo_section demo_section_shading = {8, "Shading: flat, Gouraud, Phong", demo_render_shading};
