/* The demo gallery: `cg demo` renders one picture per algorithm and writes an
 * index.html with a section per chapter of the lecture notes.
 *
 * Each tools/cg/gallery/demo_<name>.c defines `const demo_section demo_section_<name>`;
 * the build lists them by file name (cmake/registry.cmake). */
#ifndef CG_TOOL_DEMO_H
#define CG_TOOL_DEMO_H

#include "cg/image.h"

typedef struct demo_context demo_context;

typedef struct demo_section {
    int chapter;       /* chapter of the lecture notes, 2 to 11 */
    const char *title; /* heading of this group of pictures */
    /* Renders the pictures with demo_add; returns 0, or non-zero on failure. */
    int (*render)(demo_context *context);
} demo_section;

/* Saves image as FILE (a .png name, no directory) in the gallery folder and
 * adds it to the page with a caption naming the algorithm and the command
 * that reproduces it (NULL when there is none).  The command runs in the
 * gallery folder and writes FILE there (`cg demo --only ...` writes out/FILE).  Returns 0 or prints an error
 * and returns non-zero. */
int demo_add(demo_context *context, const char *file, const cg_image *image, const char *caption,
             const char *command);

/* The gallery folder, for sections that write other files (inputs of the
 * commands they show, for example). */
const char *demo_directory(const demo_context *context);

/* Copies a file of the source tree (path relative to its root, such as
 * data/meshes/bunny.obj) to the same relative path in the gallery folder, so
 * that captions naming it run there.  Does nothing in an installed tool
 * (no source tree).  Returns 0 or prints an error and returns non-zero. */
int demo_copy_input(demo_context *context, const char *relative);

#endif
