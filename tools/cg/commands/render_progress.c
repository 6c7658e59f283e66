/* Progress of long frames on stderr (see render_progress.h). */
#include "render_progress.h"

#include "cli.h"

#include <stdio.h>

void render_progress_start(render_progress *p, const char *command)
{
    p->command = command;
    p->start = cli_now();
    p->last = 0;
    p->shown = 0;
}

void render_progress_show(void *user, double fraction)
{
    render_progress *p = user;
    double now = cli_now();
    if (now - p->start < 1.0 || (now - p->last < 0.25 && fraction < 1))
        return;
    p->last = now;
    p->shown = 1;
    fprintf(stderr, "\rcg: %s: %3.0f%%", p->command, fraction * 100);
    if (fraction >= 1) {
        fputc('\n', stderr);
        p->shown = 0;
    }
    fflush(stderr);
}

void render_progress_end(render_progress *p)
{
    if (p->shown)
        render_progress_show(p, 1);
}
