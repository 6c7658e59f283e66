/* cg convert-mesh IN OUT: between OBJ, PLY, OFF, STL and glTF. */
#include "cli.h"
#include "command.h"
#include "cg/mesh.h"

#include <stddef.h>
#include <stdio.h>

typedef struct convert_mesh_arguments {
    int format; /* index into format_names, 0: by OUT's extension */
} convert_mesh_arguments;

static const char *const format_names[] = {"auto", "obj", "ply", "ply-ascii",
                                           "off",  "stl", "glb", NULL};
static const cg_mesh_format formats[] = {
    CG_MESH_FORMAT_AUTO, CG_MESH_FORMAT_OBJ, CG_MESH_FORMAT_PLY_BINARY, CG_MESH_FORMAT_PLY_ASCII,
    CG_MESH_FORMAT_OFF,  CG_MESH_FORMAT_STL, CG_MESH_FORMAT_GLTF};

static const cli_option convert_mesh_options[] = {
    {.name = "--format",
     .kind = CLI_CHOICE,
     .offset = offsetof(convert_mesh_arguments, format),
     .choices = format_names,
     .help = "the format to write; auto (the default): by OUT's extension (.obj, .ply =\n"
             "binary, .off, .stl = binary, .glb)"},
};
static const cli_option_group convert_mesh_groups[] = {CLI_GROUP(NULL, convert_mesh_options), {0}};
static const cli_syntax convert_mesh_syntax = {
    .command = "convert-mesh",
    .groups = convert_mesh_groups,
    .max_positionals = 2,
    .too_many = "expected two files, got '%s' as a third",
};
static const cli_syntax *const convert_mesh_syntaxes[] = {&convert_mesh_syntax, NULL};

static int run(int argc, char **argv)
{
    convert_mesh_arguments a = {0};
    const char *paths[2];
    int count = 0;
    if (cli_parse(&convert_mesh_syntax, argc, argv, &a, paths, &count) != CLI_OK)
        return CLI_USAGE;
    if (count != 2)
        return cli_usage_error("convert-mesh", "expected IN and OUT files");
    cg_mesh_format format = formats[a.format];
    if (format == CG_MESH_FORMAT_AUTO
        && (format = cg_mesh_format_from_path(paths[1])) == CG_MESH_FORMAT_AUTO)
        return cli_usage_error("convert-mesh",
                               "%s: unknown output format (expected .obj, .ply, .off, .stl or "
                               ".glb, or --format)",
                               paths[1]);
    cg_mesh *mesh;
    cg_error err;
    if (cg_mesh_load(paths[0], &mesh, &err) != CG_OK)
        return cli_fail("%s", err.message);
    cli_print_notes(mesh->notes);
    int status = CLI_OK;
    if (cg_mesh_save(mesh, paths[1], format, &err) != CG_OK)
        status = cli_fail("%s", err.message);
    cg_mesh_free(mesh);
    return status;
}

const cg_command cg_command_convert_mesh = {
    "convert-mesh",
    "convert a mesh between OBJ, PLY, OFF, STL and glTF",
    "usage: cg convert-mesh IN OUT [--format FORMAT]\n\n"
    "Reads IN (OBJ, PLY, OFF, STL, glTF .gltf or .glb; recognised by content,\n"
    "then extension; gzip looked through) and writes OUT, each format keeping what\n"
    "it carries: OBJ positions, texture coordinates, normals, vertex and face\n"
    "colours (the latter in a .mtl beside it); PLY (binary, or ASCII with\n"
    "--format ply-ascii) the same as doubles; OFF positions, normals, colours,\n"
    "texture coordinates and face colours; STL the triangles (faces\n"
    "triangulated, floats); glTF binary (.glb) the triangles, normals, texture\n"
    "coordinates, vertex colours and the materials' factors, one primitive per\n"
    "material.  A glTF IN gives its default scene's triangles in world space.\n"
    "OUT is replaced only when writing succeeds.\n",
    run,
    convert_mesh_syntaxes,
};
