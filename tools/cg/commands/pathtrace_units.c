/* Work units of a path-traced render, and the checkpoint that keeps them
 * (see pathtrace_units.h). */
#include "pathtrace_units.h"

#include "cli.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* 32 x 32 pixels and 16 samples: about 16,000 paths a unit, small enough
 * that ranks finish together, large enough that a unit's message (24 KiB of
 * sums) costs little beside its rendering. */
enum { UNIT_SIDE = 32, UNIT_SAMPLES = 16 };

static int ceil_div(int a, int b)
{
    return (a + b - 1) / b;
}

pathtrace_unit *pathtrace_units_plan(const cg_path_part *region, size_t *count)
{
    int x0 = (int)region->x0, y0 = (int)region->y0, x1 = (int)region->x1, y1 = (int)region->y1;
    int s0 = (int)region->sample_begin, s1 = (int)region->sample_end;
    int across = ceil_div(x1 - x0, UNIT_SIDE), down = ceil_div(y1 - y0, UNIT_SIDE);
    int ranges = ceil_div(s1 - s0, UNIT_SAMPLES);
    size_t n = (size_t)across * (size_t)down * (size_t)ranges;
    pathtrace_unit *units = malloc(n * sizeof *units);
    if (!units)
        return NULL;
    size_t k = 0;
    /* sample ranges outermost: the picture gets its first samples everywhere
     * before any pixel gets more */
    for (int r = 0; r < ranges; r++)
        for (int ty = 0; ty < down; ty++)
            for (int tx = 0; tx < across; tx++) {
                pathtrace_unit u = {x0 + tx * UNIT_SIDE,       y0 + ty * UNIT_SIDE,
                                    x0 + (tx + 1) * UNIT_SIDE, y0 + (ty + 1) * UNIT_SIDE,
                                    s0 + r * UNIT_SAMPLES,     s0 + (r + 1) * UNIT_SAMPLES};
                u.x1 = u.x1 < x1 ? u.x1 : x1;
                u.y1 = u.y1 < y1 ? u.y1 : y1;
                u.sample_end = u.sample_end < s1 ? u.sample_end : s1;
                units[k++] = u;
            }
    *count = n;
    return units;
}

size_t pathtrace_unit_values(pathtrace_unit unit)
{
    return (size_t)(unit.x1 - unit.x0) * (size_t)(unit.y1 - unit.y0) * 3;
}

cg_status pathtrace_unit_render(const pathtrace_job *job, pathtrace_unit unit, uint64_t *sums)
{
    cg_path_options o = job->options;
    o.x0 = unit.x0, o.y0 = unit.y0, o.x1 = unit.x1, o.y1 = unit.y1;
    o.sample_begin = unit.sample_begin;
    o.sample_end = unit.sample_end;
    memset(sums, 0, pathtrace_unit_values(unit) * sizeof *sums);
    return cg_path_render_sums(job->scene, job->camera, (int)job->region->width,
                               (int)job->region->height, &o, sums);
}

void pathtrace_unit_add(cg_path_part *region, pathtrace_unit unit, const uint64_t *sums)
{
    size_t region_width = region->x1 - region->x0, unit_width = (size_t)(unit.x1 - unit.x0);
    for (int y = unit.y0; y < unit.y1; y++) {
        uint64_t *to = region->sums
                       + 3
                             * ((size_t)(y - (int)region->y0) * region_width
                                + (size_t)(unit.x0 - (int)region->x0));
        const uint64_t *from = sums + 3 * (size_t)(y - unit.y0) * unit_width;
        for (size_t i = 0; i < 3 * unit_width; i++)
            to[i] += from[i];
    }
}

/* DIR/RENDER-X0-Y0-X1-Y1-S0-S1.part: RENDER digests the render key (mesh,
 * size, sky) with the seed, spp and depth, so that renders of other
 * arguments sharing the directory keep their own files; the rest names the
 * unit.  The file's header repeats them all. */
static char *checkpoint_path(const pathtrace_job *job, pathtrace_unit u)
{
    const cg_path_part *r = job->region;
    uint64_t fields[4] = {r->render_key, r->seed, r->spp, r->max_depth}, id = 0xcbf29ce484222325ull;
    const unsigned char *bytes = (const unsigned char *)fields;
    for (size_t i = 0; i < sizeof fields; i++)
        id = (id ^ bytes[i]) * 0x100000001b3ull;
    size_t n = strlen(job->checkpoint) + 128;
    char *path = malloc(n);
    if (path)
        snprintf(path, n, "%s/%016" PRIx64 "-%d-%d-%d-%d-%d-%d.part", job->checkpoint, id, u.x0,
                 u.y0, u.x1, u.y1, u.sample_begin, u.sample_end);
    return path;
}

static cg_path_part unit_part(const pathtrace_job *job, pathtrace_unit u, const uint64_t *sums)
{
    const cg_path_part *r = job->region;
    cg_path_part p = {r->width,
                      r->height,
                      (uint32_t)u.x0,
                      (uint32_t)u.y0,
                      (uint32_t)u.x1,
                      (uint32_t)u.y1,
                      (uint32_t)u.sample_begin,
                      (uint32_t)u.sample_end,
                      r->spp,
                      r->max_depth,
                      r->seed,
                      r->render_key,
                      (uint64_t *)sums};
    return p;
}

int pathtrace_checkpoint_load(const pathtrace_job *job, pathtrace_unit unit, uint64_t *sums)
{
    char *path = checkpoint_path(job, unit);
    struct stat st;
    if (!path || stat(path, &st) != 0) {
        free(path);
        return 0;
    }
    cg_path_part got;
    cg_error err;
    int found = 0;
    if (cg_path_part_load(path, &got, &err) != CG_OK) {
        fprintf(stderr, "cg: warning: --checkpoint: %s; rendering that unit again\n", err.message);
    } else {
        cg_path_part want = unit_part(job, unit, NULL);
        found = got.width == want.width && got.height == want.height && got.x0 == want.x0
                && got.y0 == want.y0 && got.x1 == want.x1 && got.y1 == want.y1
                && got.sample_begin == want.sample_begin && got.sample_end == want.sample_end
                && got.spp == want.spp && got.max_depth == want.max_depth && got.seed == want.seed
                && got.render_key == want.render_key;
        if (found)
            memcpy(sums, got.sums, pathtrace_unit_values(unit) * sizeof *sums);
        else
            fprintf(stderr,
                    "cg: warning: --checkpoint: %s belongs to another render; rendering that "
                    "unit again\n",
                    path);
        free(got.sums);
    }
    free(path);
    return found;
}

cg_status pathtrace_checkpoint_save(const pathtrace_job *job, pathtrace_unit unit,
                                    const uint64_t *sums, cg_error *err)
{
    if (mkdir(job->checkpoint, 0777) != 0 && errno != EEXIST)
        return cg_error_set(err, CG_EIO, "--checkpoint: cannot create directory %s: %s",
                            job->checkpoint, strerror(errno));
    char *path = checkpoint_path(job, unit);
    if (!path)
        return cg_error_set(err, CG_ENOMEM, "--checkpoint: out of memory");
    cg_path_part part = unit_part(job, unit, sums);
    cg_status s = cg_path_part_save(&part, path, err);
    free(path);
    return s;
}

int pathtrace_units_run(const char *command, const pathtrace_job *job)
{
    size_t count = 0, reused = 0;
    pathtrace_unit *units = pathtrace_units_plan(job->region, &count);
    uint64_t *sums = malloc((size_t)UNIT_SIDE * UNIT_SIDE * 3 * sizeof *sums);
    int status = units && sums ? CLI_OK : cli_fail("%s: out of memory", command);
    double start = cli_now();
    for (size_t k = 0; k < count && status == CLI_OK; k++) {
        cg_error err;
        if (job->checkpoint && pathtrace_checkpoint_load(job, units[k], sums)) {
            reused++;
        } else if (pathtrace_unit_render(job, units[k], sums) != CG_OK) {
            status = cli_fail("%s: path tracing failed", command);
            break;
        } else if (job->checkpoint
                   && pathtrace_checkpoint_save(job, units[k], sums, &err) != CG_OK) {
            status = cli_fail("%s: %s", command, err.message);
            break;
        }
        pathtrace_unit_add(job->region, units[k], sums);
        if (!job->quiet && (k + 1 == count || (k + 1) % 64 == 0))
            fprintf(stderr, "%s: pathtrace: %zu/%zu units, %.2f s\n", command, k + 1, count,
                    cli_now() - start);
    }
    if (status == CLI_OK && job->checkpoint && !job->quiet)
        fprintf(stderr, "%s: pathtrace: %zu of %zu units from the checkpoint\n", command, reused,
                count);
    free(sums);
    free(units);
    return status;
}
