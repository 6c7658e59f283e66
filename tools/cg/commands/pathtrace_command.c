/* `cg render MESH --algorithm pathtrace`: a mesh under a uniform sky,
 * rendered whole or as a part (--tile, --sample-range), with a time budget
 * and progress on stderr. */
#include "pathtrace_command.h"

#include "cli.h"
#include "pathtrace_input.h"
#include "pathtrace_mpi.h"
#include "pathtrace_output.h"
#include "render_scene.h"
#include "cg/image_float.h"
#include "cg/pathtrace.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct pathtrace_args {
    const char *output, *algorithm, *tile, *range, *environment, *checkpoint;
    cli_size size;
    int spp, max_depth, seed, threads, quiet, env_given, env_intensity_given, size_given;
    cg_vec3 env;
    double time, exposure, env_intensity;
} pathtrace_args;

static const cli_option pathtrace_options[] = {
    CLI_OPTION_OUTPUT(pathtrace_args, output, "OUT",
                      "the picture (.png, .pfm, ...) or, for a part, a .part file"),
    {.name = "--algorithm",
     .kind = CLI_STRING,
     .offset = offsetof(pathtrace_args, algorithm),
     .value_name = "pathtrace",
     .help = "the path tracer"},
    CLI_OPTION_SIZE(pathtrace_args, size, CLI_GIVEN(pathtrace_args, size_given),
                    "picture size (default 320x240, or a scene file's)"),
    {.name = "--spp",
     .kind = CLI_INT,
     .offset = offsetof(pathtrace_args, spp),
     .value_name = "N",
     .help = "samples per pixel (default 64)",
     .min = 1,
     .max = 1 << 24},
    {.name = "--max-depth",
     .kind = CLI_INT,
     .offset = offsetof(pathtrace_args, max_depth),
     .value_name = "N",
     .help = "surface interactions per path (default 8)",
     .min = 1,
     .max = 256},
    {.name = "--seed",
     .kind = CLI_INT,
     .offset = offsetof(pathtrace_args, seed),
     .value_name = "N",
     .help = "sample pattern (default 0)",
     .min = 0,
     .max = 0x7fffffff},
    {.name = "--environment-color",
     .kind = CLI_VEC3,
     .offset = offsetof(pathtrace_args, env),
     .value_name = "R,G,B",
     .help = "uniform sky radiance, linear (default 1,1,1)",
     .given = CLI_GIVEN(pathtrace_args, env_given)},
    {.name = "--environment",
     .kind = CLI_STRING,
     .offset = offsetof(pathtrace_args, environment),
     .value_name = "FILE",
     .help = "equirectangular sky (.hdr, .exr, .pfm; 8-bit files are sRGB), replaces "
             "--environment-color; a one-pixel file is a uniform sky"},
    {.name = "--environment-intensity",
     .kind = CLI_DOUBLE,
     .offset = offsetof(pathtrace_args, env_intensity),
     .value_name = "K",
     .help = "multiplies the --environment map's radiance (default 1)",
     .range_text = "a number >= 0",
     .low = 0,
     .high = 1e9,
     .given = CLI_GIVEN(pathtrace_args, env_intensity_given)},
    {.name = "--tile",
     .kind = CLI_STRING,
     .offset = offsetof(pathtrace_args, tile),
     .value_name = "X0,Y0,X1,Y1",
     .help = "render only this tile, to a .part file"},
    {.name = "--sample-range",
     .kind = CLI_STRING,
     .offset = offsetof(pathtrace_args, range),
     .value_name = "A..B",
     .help = "render only samples A to B-1, to a .part file"},
    {.name = "--checkpoint",
     .kind = CLI_STRING,
     .offset = offsetof(pathtrace_args, checkpoint),
     .value_name = "DIR",
     .help = "keep finished units of 32x32 pixels and 16 samples in DIR; a rerun with the "
             "same arguments renders only the missing ones"},
    {.name = "--time",
     .kind = CLI_DOUBLE,
     .offset = offsetof(pathtrace_args, time),
     .value_name = "SECONDS",
     .help = "stop after the pass that passes this budget",
     .range_text = "a number > 0",
     .low = 0,
     .high = 1e9,
     .open = CLI_OPEN_LOW},
    {.name = "--exposure",
     .kind = CLI_DOUBLE,
     .offset = offsetof(pathtrace_args, exposure),
     .value_name = "STOPS",
     .help = "exposure of 8-bit outputs (default 0)"},
    CLI_OPTION_THREADS(pathtrace_args, threads, 0, "worker threads (default 1)"),
    {.name = "--quiet",
     .kind = CLI_FLAG,
     .offset = offsetof(pathtrace_args, quiet),
     .help = "no progress on stderr",
     .flag_value = 1},
};

static const cli_option_group pathtrace_groups[] = {
    CLI_GROUP("Path tracer (--algorithm pathtrace):", pathtrace_options), {0}};

const cli_syntax pathtrace_syntax = {
    .command = "render",
    .groups = pathtrace_groups,
    .max_positionals = 1,
    .too_many = "expected one MESH, got '%s' as a second",
    .min_positionals = 1,
    .too_few = "expected a MESH file",
};

int pathtrace_requested(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--algorithm=pathtrace") == 0)
            return 1;
        if (strcmp(argv[i], "--algorithm") == 0 && i + 1 < argc
            && strcmp(argv[i + 1], "pathtrace") == 0)
            return 1;
    }
    return 0;
}

/* "X0,Y0,X1,Y1" inside the picture, or "A..B" within spp. */
static int parse_tile(const char *command, const char *text, const cli_size *size, int t[4])
{
    char end;
    if (sscanf(text, "%d,%d,%d,%d%c", &t[0], &t[1], &t[2], &t[3], &end) != 4 || t[0] < 0 || t[1] < 0
        || t[2] <= t[0] || t[3] <= t[1] || t[2] > size->width || t[3] > size->height)
        return cli_usage_error(command,
                               "--tile: expected X0,Y0,X1,Y1 with 0 <= X0 < X1 <= %d and "
                               "0 <= Y0 < Y1 <= %d, got '%s'",
                               size->width, size->height, text);
    return CLI_OK;
}

static int parse_range(const char *command, const char *text, int spp, int r[2])
{
    char end;
    if (sscanf(text, "%d..%d%c", &r[0], &r[1], &end) != 2 || r[0] < 0 || r[1] <= r[0] || r[1] > spp)
        return cli_usage_error(command,
                               "--sample-range: expected A..B with 0 <= A < B <= %d (--spp), "
                               "got '%s'",
                               spp, text);
    return CLI_OK;
}

/* Renders passes of growing sample counts until spp or the time budget. */
static int render_passes(const char *command, cg_trace_scene *scene, const cg_camera *camera,
                         const pathtrace_args *a, cg_path_options *o, cg_path_part *part)
{
    int begin = o->sample_begin, end = o->sample_end, chunk = 1, done = begin;
    double start = cli_now();
    while (done < end) {
        o->sample_begin = done;
        o->sample_end = done + chunk < end ? done + chunk : end;
        cg_status s = cg_path_render_sums(scene, camera, a->size.width, a->size.height, o,
                                          part->sums);
        if (s != CG_OK)
            return cli_fail("%s: path tracing failed: %s", command, cg_status_str(s));
        done = o->sample_end;
        double t = cli_now() - start;
        if (!a->quiet)
            fprintf(stderr, "%s: pathtrace: %d/%d samples, %.2f s\n", command, done - begin,
                    end - begin, t);
        if (a->time > 0 && t >= a->time)
            break;
        chunk = chunk < 64 ? chunk * 2 : 64;
    }
    part->sample_begin = (uint32_t)begin;
    part->sample_end = (uint32_t)done;
    return CLI_OK;
}

/* Renders the loaded input: the whole picture or the part --tile and
 * --sample-range name, in passes, over units (--checkpoint) or over MPI
 * ranks, and writes it. */
static int render_input(const char *command, const pathtrace_input *in, const pathtrace_args *a)
{
    int tile[4] = {0, 0, a->size.width, a->size.height}, range[2] = {0, a->spp};
    if (a->tile && parse_tile(command, a->tile, &a->size, tile) != CLI_OK)
        return CLI_USAGE;
    if (a->range && parse_range(command, a->range, a->spp, range) != CLI_OK)
        return CLI_USAGE;
    int split = a->tile || a->range;
    if (split && !pathtrace_is_part(a->output))
        return cli_usage_error(command, "--tile and --sample-range write a .part file, not '%s'",
                               a->output);
    if (split && a->time > 0)
        return cli_usage_error(command, "--time renders whole pictures only");
    int ranks = pathtrace_mpi_ranks();
    if (a->time > 0 && (a->checkpoint || ranks > 1))
        return cli_usage_error(command, "--time renders in one process without --checkpoint");
    cg_path_options o = cg_path_options_default();
    o.environment_map = in->environment_map;
    o.environment_intensity = in->environment_intensity;
    o.environment = in->environment;
    o.spp = a->spp;
    o.max_depth = a->max_depth;
    o.threads = a->threads;
    o.seed = (uint64_t)a->seed;
    o.x0 = tile[0], o.y0 = tile[1], o.x1 = tile[2], o.y1 = tile[3];
    o.sample_begin = range[0];
    o.sample_end = range[1];
    cg_path_part part = {(uint32_t)a->size.width,
                         (uint32_t)a->size.height,
                         (uint32_t)tile[0],
                         (uint32_t)tile[1],
                         (uint32_t)tile[2],
                         (uint32_t)tile[3],
                         (uint32_t)range[0],
                         (uint32_t)range[1],
                         (uint32_t)a->spp,
                         (uint32_t)a->max_depth,
                         o.seed,
                         in->key,
                         NULL};
    part.sums = calloc((size_t)(tile[2] - tile[0]) * (size_t)(tile[3] - tile[1]) * 3, 8);
    pathtrace_job job = {in->scene, &in->camera, o, &part, a->checkpoint, a->quiet};
    int writer = 1, status;
    if (!part.sums)
        status = cli_fail("%s: out of memory", command);
    else if (ranks > 1)
        status = pathtrace_mpi_render(command, &job, &writer);
    else if (a->checkpoint)
        status = pathtrace_units_run(command, &job);
    else
        status = render_passes(command, in->scene, &in->camera, a, &o, &part);
    if (status == CLI_OK && !split)
        part.spp = part.sample_end; /* a time budget may have stopped it early */
    if (status == CLI_OK && writer)
        status = pathtrace_write(command, &part, a->output, a->exposure);
    if (ranks > 1)
        pathtrace_mpi_finish();
    free(part.sums);
    return status;
}

static int render(const char *command, const char *input, pathtrace_args *a)
{
    cg_error err = {0};
    pathtrace_input in;
    pathtrace_sky sky = {a->environment, a->env, a->env_intensity, a->env_given,
                         a->env_intensity_given};
    cg_status loaded = pathtrace_input_load(input, a->size, a->size_given, &sky, &in, &err);
    if (loaded == CG_EINVAL)
        return cli_usage_error(command, "%s", err.message);
    if (loaded != CG_OK)
        return cli_fail("%s: %s", command, err.message);
    a->size = (cli_size){in.width, in.height};
    int status = render_input(command, &in, a);
    pathtrace_input_free(&in);
    return status;
}

int pathtrace_command_run(const char *command, int argc, char **argv)
{
    pathtrace_args a;
    memset(&a, 0, sizeof a);
    a.size.width = 320;
    a.size.height = 240;
    a.spp = 64;
    a.max_depth = 8;
    a.threads = 1;
    a.env = cg_vec3_make(1, 1, 1);
    a.env_intensity = 1;
    const char *input[1] = {NULL};
    int count = 0;
    if (cli_parse(&pathtrace_syntax, argc, argv, &a, input, &count) != CLI_OK)
        return CLI_USAGE;
    if (!a.output)
        return cli_usage_error(command, "expected -o OUT");
    if (a.env_given && !(a.env.x >= 0 && a.env.y >= 0 && a.env.z >= 0))
        return cli_usage_error(command, "--environment-color: expected R,G,B >= 0");
    if (a.environment && a.env_given)
        return cli_usage_error(command, "--environment and --environment-color: give one sky");
    return render(command, input[0], &a);
}
