/* Progress of long frames on stderr, for every renderer of `cg render` and
 * `cg trace-render`: nothing for frames under a second, then the percentage
 * done ("cg: render: 42%"), at most four times a second. */
#ifndef CG_TOOL_RENDER_PROGRESS_H
#define CG_TOOL_RENDER_PROGRESS_H

typedef struct render_progress {
    const char *command;
    double start, last;
    int shown;
} render_progress;

/* Before each frame. */
void render_progress_start(render_progress *p, const char *command);
/* The callback of cg_render_options.progress (user is the render_progress). */
void render_progress_show(void *user, double fraction);
/* After each frame: ends the line if one was shown. */
void render_progress_end(render_progress *p);

#endif
