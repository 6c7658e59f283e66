/* `cg trace` for chapter 9's operations on the half-edge structure: the
 * Loop and Catmull-Clark stencils of a vertex and an edge flip, split or
 * collapse with the half-edge records before and after. */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/hemesh.h"
#include "cg/trace_steps.h"

#include <string.h>

int trace_load_hemesh(const char *path, cg_hemesh **out)
{
    cg_mesh *mesh;
    cg_error err;
    if (cg_mesh_load(path, &mesh, &err) != CG_OK)
        return cli_fail("trace: %s", err.message);
    cg_status status = cg_hemesh_build(mesh, 0, out, NULL, &err);
    cg_mesh_free(mesh);
    if (status != CG_OK)
        return cli_fail("trace: %s: %s", path, err.message);
    return CLI_OK;
}

/* loop MESH V and catmull-clark MESH V */
static int run_stencil(int loop, int argc, char **argv, const trace_outputs *out)
{
    long index;
    if (argc != 3)
        return cli_usage_error("trace", "%s: expected '%s MESH V'", argv[0], argv[0]);
    if (trace_parse_int("V", argv[2], 0, 4294967293L, &index))
        return CLI_USAGE;
    cg_hemesh *m;
    if (trace_load_hemesh(argv[1], &m) != CLI_OK)
        return CLI_FAILED;
    if ((size_t)index >= m->vertex_count) {
        cg_hemesh_free(m);
        return cli_usage_error("trace", "%s: %s has %zu vertices, no vertex %ld", argv[0], argv[1],
                               m->vertex_count, index);
    }
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1,
                                      "The %s stencil of vertex %ld of %s",
                                      loop ? "Loop" : "Catmull-Clark", index, argv[1]);
    if (!run) {
        cg_hemesh_free(m);
        return cli_fail("trace: out of memory");
    }
    run->y_up = 1;
    if (loop)
        trace_note(run, "interior: new P = (1 - n beta) P + beta (sum of the n neighbours), beta "
                        "= (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n (Loop, 1987)");
    else
        trace_note(run, "interior: new P = (F + 2R + (n - 3) P) / n, F the average of the n face "
                        "points (centroids), R of the n edge midpoints (Catmull-Clark, 1978)");
    trace_note(run, "boundary: new P = 3/4 P + 1/8 (a + b), a and b the neighbours along the "
                    "boundary; the weights of each term are those of the whole stencil");
    trace_note(run, "the frames show x and y of the positions, each term joined to P");
    cg_status status = loop ? cg_hemesh_loop_stencil_steps(m, (uint32_t)index, cg_step_log_record,
                                                           run->log)
                            : cg_hemesh_catmull_clark_stencil_steps(m, (uint32_t)index,
                                                                    cg_step_log_record, run->log);
    cg_hemesh_free(m);
    if (status == CG_EUNSUPPORTED) {
        trace_run_free(run);
        return cli_usage_error("trace",
                               "loop: %s has faces that are not triangles (Loop "
                               "subdivides triangles; try catmull-clark)",
                               argv[1]);
    }
    return trace_finish(run, status, "no such vertex", out);
}

static int run_loop(int argc, char **argv, const trace_outputs *out)
{
    return run_stencil(1, argc, argv, out);
}

static int run_catmull_clark(int argc, char **argv, const trace_outputs *out)
{
    return run_stencil(0, argc, argv, out);
}

/* edge-flip|edge-split|edge-collapse MESH E */
static int run_edge(cg_edge_operation operation, int argc, char **argv, const trace_outputs *out)
{
    long index;
    if (argc != 3)
        return cli_usage_error("trace",
                               "%s: expected '%s MESH E' (E an edge: half-edges 2E and "
                               "2E + 1)",
                               argv[0], argv[0]);
    if (trace_parse_int("E", argv[2], 0, 2147483646L, &index))
        return CLI_USAGE;
    cg_hemesh *m;
    if (trace_load_hemesh(argv[1], &m) != CLI_OK)
        return CLI_FAILED;
    if ((size_t)index >= m->halfedge_count / 2) {
        cg_hemesh_free(m);
        return cli_usage_error("trace", "%s: %s has %zu edges, no edge %ld", argv[0], argv[1],
                               m->halfedge_count / 2, index);
    }
    trace_run *run = trace_run_create(argv[0], argc - 1, argv + 1, "%s of edge %ld of %s",
                                      operation == CG_EDGE_FLIP    ? "Flip"
                                      : operation == CG_EDGE_SPLIT ? "Split"
                                                                   : "Collapse",
                                      index, argv[1]);
    if (!run) {
        cg_hemesh_free(m);
        return cli_fail("trace: out of memory");
    }
    run->y_up = 1;
    trace_note(run, "edge E is the half-edges h = 2E and twin(h) = 2E + 1; each record: origin, "
                    "dest, twin = h xor 1, next, prev, face (boundary: none)");
    trace_note(run, "before: the half-edges leaving the edge's ends and the corners opposite it; "
                    "after: the same around the vertices still there (and a new one)");
    static const char *const rules[3] = {
        "flip: triangles (a, b, c) and (b, a, d) become (c, d, b) and (d, c, a); refused on "
        "the boundary, on non-triangles, when c and d are already joined",
        "split: a new vertex at the midpoint, joined to the opposite corner of each adjacent "
        "triangle",
        "collapse of h = 2E: origin(h) is removed and its edges join dest(h); refused when the "
        "link condition fails"};
    trace_note(run, "%s", rules[operation]);
    cg_status status = cg_hemesh_edge_operation_steps(m, operation, (uint32_t)index,
                                                      cg_step_log_record, run->log);
    cg_hemesh_free(m);
    return trace_finish(run, status, "no such edge", out);
}

static int run_edge_flip(int argc, char **argv, const trace_outputs *out)
{
    return run_edge(CG_EDGE_FLIP, argc, argv, out);
}

static int run_edge_split(int argc, char **argv, const trace_outputs *out)
{
    return run_edge(CG_EDGE_SPLIT, argc, argv, out);
}

static int run_edge_collapse(int argc, char **argv, const trace_outputs *out)
{
    return run_edge(CG_EDGE_COLLAPSE, argc, argv, out);
}

const trace_algorithm trace_mesh_ops_algorithms[] = {
    {"loop", "MESH V", run_loop},
    {"catmull-clark", "MESH V", run_catmull_clark},
    {"edge-flip", "MESH E", run_edge_flip},
    {"edge-split", "MESH E", run_edge_split},
    {"edge-collapse", "MESH E", run_edge_collapse},
    {NULL, NULL, NULL},
};
