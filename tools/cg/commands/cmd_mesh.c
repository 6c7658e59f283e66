/* cg mesh info|subdivide|repair: the half-edge structure from the command
 * line. */
#include "cli.h"
#include "command.h"
#include "cg/hemesh.h"
#include "cg/mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const unsigned repair_flags = CG_HEMESH_REPAIR;

static int load(const char *path, cg_mesh **mesh)
{
    cg_error err;
    if (cg_mesh_load(path, mesh, &err) != CG_OK)
        return cli_fail("%s", err.message);
    cli_print_notes((*mesh)->notes);
    return CLI_OK;
}

/* Builds with every repair; fails with the library's message. */
static int build(const char *what, const cg_mesh *mesh, cg_hemesh **out, cg_hemesh_report *report)
{
    cg_error err;
    if (cg_hemesh_build(mesh, repair_flags, out, report, &err) != CG_OK) {
        cg_hemesh_report_clear(report);
        return cli_fail("mesh %s: %s", what, err.message);
    }
    return CLI_OK;
}

static void print_list(FILE *f, const char *key, const uint32_t *list, size_t count, size_t stride)
{
    fprintf(f, "%s:", key);
    size_t shown = count < 20 ? count : 20;
    for (size_t i = 0; i < shown; i++) {
        if (stride == 2)
            fprintf(f, " %u-%u", list[2 * i], list[2 * i + 1]);
        else
            fprintf(f, " %u", list[i]);
    }
    fprintf(f, "%s\n", count > shown ? " ..." : "");
}

/* What the repairing build changed, one line each, to f. */
static void print_changes(FILE *f, const char *prefix, const cg_hemesh_report *r)
{
    if (r->bad_face_count) {
        fprintf(f,
                "%sdropped %zu face%s with fewer than 3 corners, a vertex out of range or a "
                "repeated vertex; ",
                prefix, r->bad_face_count, r->bad_face_count == 1 ? "" : "s");
        print_list(f, "faces (counted from 0)", r->bad_faces, r->bad_face_count, 1);
    }
    if (r->flipped_face_count)
        fprintf(f, "%sreversed %zu face%s to orient each component consistently\n", prefix,
                r->flipped_face_count, r->flipped_face_count == 1 ? "" : "s");
    if (!r->orientable)
        fprintf(f, "%sa component is not orientable: cut along %zu edge%s\n", prefix,
                r->misoriented_edge_count, r->misoriented_edge_count == 1 ? "" : "s");
    if (r->nonmanifold_edge_count) {
        fprintf(f, "%sseparated the extra faces of %zu edge%s with more than two faces; ", prefix,
                r->nonmanifold_edge_count, r->nonmanifold_edge_count == 1 ? "" : "s");
        print_list(f, "edges (vertices counted from 0)", r->nonmanifold_edges,
                   r->nonmanifold_edge_count, 2);
    }
    if (r->split_edge_count)
        fprintf(f,
                "%ssplit %zu edge%s at the midpoint where, once separated, two edges joined "
                "the same two vertices\n",
                prefix, r->split_edge_count, r->split_edge_count == 1 ? "" : "s");
    if (r->added_vertex_count) {
        fprintf(f, "%ssplit %zu non-manifold %s into one per fan (%zu vertices added); ", prefix,
                r->nonmanifold_vertex_count,
                r->nonmanifold_vertex_count == 1 ? "vertex" : "vertices", r->added_vertex_count);
        print_list(f, "vertices (counted from 0)", r->nonmanifold_vertices,
                   r->nonmanifold_vertex_count, 1);
    }
}

static int repaired(const cg_hemesh_report *r)
{
    return r->bad_face_count || r->flipped_face_count || r->cut_edge_count || r->added_vertex_count
           || r->split_edge_count;
}

static void print_genus(const cg_hemesh_stats *st, const long *genus, size_t genus_count)
{
    if (st->genus >= 0) {
        printf("genus: %ld\n", st->genus);
        return;
    }
    printf("genus: mixed\n");
    printf("genus_per_component:");
    for (size_t i = 0; i < genus_count && i < 64; i++)
        printf(" %ld", genus[i]);
    printf("%s\n", genus_count > 64 ? " ..." : "");
}

/* ---- info -------------------------------------------------------------------- */

/* The `key: value` lines of cg mesh info. */
static void print_info(const char *path, const cg_mesh *mesh, const cg_hemesh_input_counts *input,
                       const cg_hemesh_stats *st, const long *genus, size_t genus_count,
                       const cg_hemesh_report *rep)
{
    printf("file: %s\n", path);
    printf("vertices: %zu\n", input->vertices);
    printf("edges: %zu\n", input->edges);
    printf("faces: %zu\n", input->faces);
    printf("boundary_loops: %zu\n", st->boundary_loops);
    printf("components: %zu\n", input->components);
    printf("euler_characteristic: %ld\n", input->euler_characteristic);
    print_genus(st, genus, genus_count);
    if (st->vertices != input->vertices || st->edges != input->edges || st->faces != input->faces
        || st->components != input->components)
        printf("genus_note: boundary_loops and genus are of the repaired manifold (the "
               "repaired_ counts), the other counts of the input\n");
    int manifold = rep->nonmanifold_edge_count == 0 && rep->nonmanifold_vertex_count == 0;
    printf("manifold: %s\n", manifold ? "yes" : "no");
    printf("oriented: %s\n", rep->misoriented_edge_count == 0 ? "yes" : "no");
    printf("orientable: %s\n", rep->orientable ? "yes" : "no");
    printf("isolated_vertices: %zu\n", input->isolated_vertices);
    printf("nonmanifold_edges: %zu\n", rep->nonmanifold_edge_count);
    printf("nonmanifold_vertices: %zu\n", rep->nonmanifold_vertex_count);
    printf("misoriented_edges: %zu\n", rep->misoriented_edge_count);
    printf("bad_faces: %zu\n", rep->bad_face_count);
    printf("face_kind: %s\n", st->all_triangles ? "triangles"
                              : st->all_quads   ? "quads"
                                                : "polygons");
    cg_vec3 lo, hi;
    if (cg_mesh_bounds(mesh, &lo, &hi) == CG_OK) {
        printf("bounding_box_min: %.9g %.9g %.9g\n", lo.x, lo.y, lo.z);
        printf("bounding_box_max: %.9g %.9g %.9g\n", hi.x, hi.y, hi.z);
    } else {
        printf("bounding_box_min: none\nbounding_box_max: none\n");
    }
    printf("repaired_vertices: %zu\n", st->vertices);
    printf("repaired_edges: %zu\n", st->edges);
    printf("repaired_faces: %zu\n", st->faces);
    printf("repaired_components: %zu\n", st->components);
    printf("repaired_euler_characteristic: %ld\n", st->euler_characteristic);
    if (repaired(rep))
        print_changes(stdout, "repaired: ", rep);
}

/* --repeat N: N builds and N one-ring traversals, their median times on
 * stderr. */
static int time_repeats(const cg_mesh *mesh, const cg_hemesh *h, long repeat)
{
    int status = CLI_OK;
    double *build_times = malloc((size_t)repeat * sizeof *build_times);
    double *ring_times = malloc((size_t)repeat * sizeof *ring_times);
    cg_vec3 *average = malloc((h->vertex_count ? h->vertex_count : 1) * sizeof *average);
    if (!build_times || !ring_times || !average) {
        status = cli_fail("mesh info: out of memory");
    } else {
        for (long i = 0; i < repeat && status == CLI_OK; i++) {
            cg_hemesh *again = NULL;
            double t0 = cli_now();
            cg_status s = cg_hemesh_build(mesh, repair_flags, &again, NULL, NULL);
            build_times[i] = cli_now() - t0;
            cg_hemesh_free(again);
            if (s != CG_OK)
                status = cli_fail("mesh info: build failed on repeat %ld", i + 1);
            t0 = cli_now();
            cg_hemesh_neighbor_average(h, average);
            ring_times[i] = cli_now() - t0;
        }
        if (status == CLI_OK) {
            /* as `build: 12.3 ms`; three decimals below a millisecond */
            double b = 1e3 * cli_median(build_times, (int)repeat);
            double r = 1e3 * cli_median(ring_times, (int)repeat);
            fprintf(stderr, b >= 1 ? "build: %.1f ms\n" : "build: %.3f ms\n", b);
            fprintf(stderr, r >= 1 ? "one-ring: %.1f ms\n" : "one-ring: %.3f ms\n", r);
        }
    }
    free(build_times);
    free(ring_times);
    free(average);
    return status;
}

typedef struct info_arguments {
    int repeat;
} info_arguments;

static const cli_option info_options[] = {
    CLI_OPTION_REPEAT(info_arguments, repeat, 100000,
                      "build N times; the median build and one-ring times on stderr"),
};
static const cli_option_group info_groups[] = {CLI_GROUP(NULL, info_options), {0}};
static const cli_syntax info_syntax = {
    .command = "mesh",
    .action = "info",
    .groups = info_groups,
    .max_positionals = 1,
    .too_many = "info: expected one FILE, got '%s' as a second",
    .min_positionals = 1,
    .too_few = "info: expected a mesh FILE",
};

static int info(int argc, char **argv)
{
    const char *path = NULL;
    info_arguments arguments = {0};
    if (cli_parse(&info_syntax, argc, argv, &arguments, &path, NULL) != CLI_OK)
        return CLI_USAGE;
    long repeat = arguments.repeat;
    cg_mesh *mesh;
    if (load(path, &mesh))
        return CLI_FAILED;
    cg_hemesh *h = NULL;
    cg_hemesh_report rep;
    if (build("info", mesh, &h, &rep)) {
        cg_mesh_free(mesh);
        return CLI_FAILED;
    }
    cg_hemesh_stats st;
    cg_hemesh_input_counts input;
    long *genus = NULL;
    size_t genus_count = 0;
    if (cg_hemesh_input_counts_compute(mesh, &input) != CG_OK
        || cg_hemesh_stats_compute(h, &st, &genus, &genus_count) != CG_OK) {
        cg_hemesh_free(h);
        cg_mesh_free(mesh);
        cg_hemesh_report_clear(&rep);
        return cli_fail("mesh info: out of memory");
    }
    print_info(path, mesh, &input, &st, genus, genus_count, &rep);
    free(genus);
    cg_hemesh_report_clear(&rep);
    int status = repeat > 0 ? time_repeats(mesh, h, repeat) : CLI_OK;
    cg_hemesh_free(h);
    cg_mesh_free(mesh);
    return status;
}

/* ---- subdivide and repair ------------------------------------------------------- */

static int save(const cg_hemesh *h, const char *path)
{
    cg_mesh *out = NULL;
    if (cg_hemesh_to_mesh(h, &out) != CG_OK)
        return cli_fail("mesh: out of memory");
    cg_error err;
    cg_status s = cg_mesh_save(out, path, CG_MESH_FORMAT_AUTO, &err);
    cg_mesh_free(out);
    if (s != CG_OK)
        return cli_fail("%s", err.message);
    return CLI_OK;
}

/* Writes h to path, then frees it: the exit status. */
static int save_and_free(cg_hemesh *h, const char *path)
{
    int status = save(h, path);
    cg_hemesh_free(h);
    return status;
}

static int check_output(const char *what, const char *path)
{
    cg_mesh_format f = cg_mesh_format_from_path(path);
    if (f != CG_MESH_FORMAT_OBJ && f != CG_MESH_FORMAT_PLY && f != CG_MESH_FORMAT_PLY_ASCII
        && f != CG_MESH_FORMAT_PLY_BINARY)
        return cli_usage_error("mesh", "%s: %s: cg writes .obj and .ply meshes", what, path);
    return CLI_OK;
}

/* Checks OUT's format, then loads IN and builds it with every repair; what
 * the repair changed is printed to `to`, each line after prefix.  *changed
 * says whether it changed anything. */
static int load_for_output(const char *what, const char *in, const char *out, FILE *to,
                           const char *prefix, cg_hemesh **h, int *changed)
{
    if (check_output(what, out))
        return CLI_USAGE;
    cg_mesh *mesh;
    if (load(in, &mesh))
        return CLI_FAILED;
    cg_hemesh_report report;
    int status = build(what, mesh, h, &report);
    cg_mesh_free(mesh);
    if (status)
        return status;
    *changed = repaired(&report);
    if (*changed)
        print_changes(to, prefix, &report);
    cg_hemesh_report_clear(&report);
    return CLI_OK;
}

/* --loop N or --catmull-clark N: the scheme, and the levels in either. */
typedef struct subdivide_arguments {
    int loop_levels, catmull_clark_levels;
    int loop_given, catmull_clark_given;
} subdivide_arguments;

static const cli_option subdivide_options[] = {
    {.name = "--loop",
     .kind = CLI_INT,
     .offset = offsetof(subdivide_arguments, loop_levels),
     .value_name = "N",
     .what = "subdivision levels",
     .min = 0,
     .max = 12,
     .given = CLI_GIVEN(subdivide_arguments, loop_given),
     .help = "N levels of Loop subdivision (triangle meshes)"},
    {.name = "--catmull-clark",
     .kind = CLI_INT,
     .offset = offsetof(subdivide_arguments, catmull_clark_levels),
     .value_name = "N",
     .what = "subdivision levels",
     .min = 0,
     .max = 12,
     .given = CLI_GIVEN(subdivide_arguments, catmull_clark_given),
     .help = "N levels of Catmull-Clark subdivision (any polygons)"},
};
static const cli_option_group subdivide_groups[] = {CLI_GROUP(NULL, subdivide_options), {0}};
static const cli_syntax subdivide_syntax = {
    .command = "mesh",
    .action = "subdivide",
    .groups = subdivide_groups,
    .max_positionals = 2,
    .too_many = "subdivide: expected IN and OUT, got '%s' as a third",
};

static int subdivide(int argc, char **argv)
{
    subdivide_arguments arguments = {0, 0, 0, 0};
    const char *paths[2];
    int count = 0;
    if (cli_parse(&subdivide_syntax, argc, argv, &arguments, paths, &count) != CLI_OK)
        return CLI_USAGE;
    if (arguments.loop_given + arguments.catmull_clark_given > 1)
        return cli_usage_error("mesh", "subdivide: give one of --loop and --catmull-clark");
    int scheme = arguments.loop_given            ? 1
                 : arguments.catmull_clark_given ? 2
                                                 : 0; /* 1 Loop, 2 Catmull-Clark */
    long levels = scheme == 1 ? arguments.loop_levels : arguments.catmull_clark_levels;
    if (!scheme)
        return cli_usage_error("mesh", "subdivide: expected --loop N or --catmull-clark N");
    if (count != 2)
        return cli_usage_error("mesh", "subdivide: expected IN and OUT files");
    cg_hemesh *h = NULL;
    int changed;
    int status = load_for_output("subdivide", paths[0], paths[1], stderr,
                                 "cg: mesh subdivide: input repaired: ", &h, &changed);
    if (status)
        return status;
    /* the result grows fourfold per level: refuse what cannot fit */
    double faces = (double)h->live_faces, corners = 0;
    for (uint32_t f = 0; f < h->face_count; f++)
        corners += (double)cg_hemesh_face_size(h, f);
    double predicted = scheme == 1 ? faces : corners;
    for (long l = scheme == 1 ? 0 : 1; l < levels; l++)
        predicted *= 4;
    if (levels > 0 && predicted * 4 > 2.0e9) {
        cg_hemesh_free(h);
        return cli_fail("mesh subdivide: %ld levels would make about %.3g faces; at most 5e8 "
                        "are supported",
                        levels, predicted);
    }
    for (long l = 0; l < levels; l++) {
        cg_hemesh *next = NULL;
        cg_status s = scheme == 1 ? cg_hemesh_subdivide_loop(h, &next)
                                  : cg_hemesh_subdivide_catmull_clark(h, &next);
        cg_hemesh_free(h);
        h = next;
        if (s == CG_EUNSUPPORTED)
            return cli_fail("mesh subdivide: %s: Loop subdivision needs a triangle mesh; use "
                            "--catmull-clark for other polygons",
                            paths[0]);
        if (s != CG_OK)
            return cli_fail("mesh subdivide: %s", cg_status_str(s));
    }
    return save_and_free(h, paths[1]);
}

static const cli_syntax repair_syntax = {
    .command = "mesh",
    .action = "repair",
    .max_positionals = 2,
    .too_many = "repair: expected IN and OUT, got '%s' as a third",
    .min_positionals = 2,
    .too_few = "repair: expected IN and OUT files",
};

static int repair(int argc, char **argv)
{
    const char *paths[2];
    if (cli_parse(&repair_syntax, argc, argv, NULL, paths, NULL) != CLI_OK)
        return CLI_USAGE;
    cg_hemesh *h = NULL;
    int changed;
    int status = load_for_output("repair", paths[0], paths[1], stdout, "", &h, &changed);
    if (status)
        return status;
    if (!changed)
        printf("nothing to repair: the mesh is a consistently oriented manifold\n");
    return save_and_free(h, paths[1]);
}

static int run(int argc, char **argv)
{
    static const cli_action actions[] = {{"info", info},
                                         {"subdivide", subdivide},
                                         {"repair", repair}};
    return cli_run_action("mesh", argc, argv, actions, 3, NULL, NULL);
}

static const cli_syntax *const mesh_syntaxes[] = {&info_syntax, &subdivide_syntax, NULL};

const cg_command cg_command_mesh = {
    "mesh",
    "half-edge mesh tools: topology report, subdivision, repair",
    "usage: cg mesh info FILE [--repeat N]\n"
    "       cg mesh subdivide --loop|--catmull-clark N IN OUT\n"
    "       cg mesh repair IN OUT\n\n"
    "FILE and IN are OBJ, OFF, PLY or STL (optionally .gz); OUT is .obj or .ply.\n\n"
    "info builds the half-edge structure (repairing as `repair` does) and prints\n"
    "one `key: value` a line: vertices, edges (distinct vertex pairs joined by a\n"
    "face side), faces, boundary_loops, components (faces joined through shared\n"
    "vertices; an isolated vertex is one), euler_characteristic (V - E + F),\n"
    "genus (one number, or `mixed` with genus_per_component), manifold (yes/no:\n"
    "no edge on more than two faces, no vertex whose faces form several fans),\n"
    "oriented (yes/no: no edge two faces run the same way), orientable,\n"
    "isolated_vertices, the counts of each defect, face_kind, the bounding box,\n"
    "then repaired_vertices, repaired_edges, repaired_faces, repaired_components\n"
    "and repaired_euler_characteristic, and a `repaired:` line for each change.\n"
    "vertices, edges, faces, components and euler_characteristic describe FILE\n"
    "as read (faces without bad faces); boundary_loops and genus are of the\n"
    "repaired manifold, per component, and a genus_note line says so when the\n"
    "repair changed the counts.  --repeat N builds the structure N times and\n"
    "prints on stderr the median build time and the median time of a one-ring\n"
    "traversal of every vertex: `build: 12.3 ms`, `one-ring: 4.5 ms`.\n\n"
    "subdivide applies N levels (0 to 12) of Loop (triangles only) or\n"
    "Catmull-Clark (any polygons; the result is quads) subdivision.\n\n"
    "repair writes IN with these changes, each reported on stdout:\n"
    "  - faces with fewer than 3 corners, a vertex index out of range or a\n"
    "    repeated vertex are dropped;\n"
    "  - faces are reversed so that each connected component is consistently\n"
    "    oriented (its first face's orientation wins); a non-orientable component\n"
    "    (Moebius strip) is cut along the edges that still disagree;\n"
    "  - the faces of an edge on more than two faces are paired by their angle\n"
    "    about it, each with its neighbour across the solid between them (a face\n"
    "    with its reversed copy), and the pairs separated along it;\n"
    "  - a vertex whose faces form several fans (touching at a point) becomes one\n"
    "    vertex per fan, the copies added at the end with the same attributes;\n"
    "  - where two edges then join the same two vertices, all but one are split\n"
    "    at the midpoint (triangles stay triangles), so the written mesh is a\n"
    "    manifold and repairing it again changes nothing.\n"
    "Vertex order, attributes, face order and face colours are otherwise kept;\n"
    "isolated vertices are kept.\n",
    run,
    mesh_syntaxes,
};
