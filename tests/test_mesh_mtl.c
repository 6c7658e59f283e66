/* OBJ materials from .mtl libraries into the mesh's material table: every
 * statement cg reads, map options and file names (relative to the .mtl,
 * spaces and backslashes), per-face material ids, and the notes for a
 * missing texture or library.  Files are written to a temporary folder. */
#include "cg.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[64];

static void write_file(const char *name, const char *text)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    fputs(text, f);
    fclose(f);
}

static const cg_mesh_material *find(const cg_mesh *mesh, const char *name)
{
    for (size_t m = 0; m < mesh->material_count; m++)
        if (strcmp(mesh->materials[m].name, name) == 0)
            return &mesh->materials[m];
    return NULL;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = s ? strlen(s) : 0, k = strlen(tail);
    return s && n >= k && strcmp(s + n - k, tail) == 0;
}

static cg_mesh *load(const char *name, cg_error *err)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    cg_mesh *mesh = NULL;
    cg_error_clear(err);
    cg_mesh_load(path, &mesh, err);
    return mesh;
}

static void statements(void)
{
    write_file("lib/wood grain.png", "not read here");
    write_file("lib/bump.png", "x");
    write_file("lib/normals.png", "x");
    write_file("lib/spec.png", "x");
    write_file("lib/alpha.png", "x");
    write_file("lib/materials.mtl", "# every statement\n"
                                    "newmtl Polished Wood Floor\n"
                                    "Ka 0.1 0.1 0.1\n"
                                    "Kd 0.8 0.6 0.4\n"
                                    "Ks 0.5 0.25 0.125\n"
                                    "Ns 96\n"
                                    "Ke 0.5 0 0\n"
                                    "d 0.75\n"
                                    "illum 3\n"
                                    "map_Kd -s 2 4 -o 0.5 0.25 -clamp on wood grain.png\n"
                                    "map_Ks spec.png\n"
                                    "map_d -imfchan m alpha.png\n"
                                    "map_bump -bm 0.3 bump.png\n"
                                    "norm normals.png\n"
                                    "\n"
                                    "newmtl glass\n"
                                    "Kd 0.5\n"
                                    "Tr 0.9\n"
                                    "bump .\\bump.png\n"
                                    "newmtl unused\n"
                                    "Kd 1 0 0\n"
                                    "map_Kd missing.png\n"
                                    "newmtl plain\n"
                                    "illum 1\n"
                                    "map_Kd missing texture.png\n");
    write_file("model.obj", "mtllib lib/materials.mtl\n"
                            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                            "f 1 2 3\n"
                            "usemtl Polished Wood Floor\n"
                            "f 2 4 3\n"
                            "usemtl glass\n"
                            "f 1 2 4\n"
                            "usemtl plain\n"
                            "f 1 4 3\n"
                            "usemtl Polished Wood Floor\n"
                            "f 1 3 4\n");
    cg_error err;
    cg_mesh *mesh = load("model.obj", &err);
    CHECK_MSG(mesh != NULL, "%s", err.message);
    if (!mesh)
        return;
    CHECK_EQ_INT(mesh->material_count, 3); /* the materials the faces use */
    const cg_mesh_material *wood = find(mesh, "Polished Wood Floor");
    const cg_mesh_material *glass = find(mesh, "glass");
    const cg_mesh_material *plain = find(mesh, "plain");
    CHECK(wood && glass && plain && !find(mesh, "unused"));
    if (!wood || !glass || !plain) {
        cg_mesh_free(mesh);
        return;
    }
    /* face materials: none, wood, glass, plain, wood */
    CHECK(mesh->face_materials != NULL);
    uint32_t w = (uint32_t)(wood - mesh->materials), g = (uint32_t)(glass - mesh->materials),
             p = (uint32_t)(plain - mesh->materials);
    CHECK(mesh->face_materials[0] == CG_MESH_NO_MATERIAL && mesh->face_materials[1] == w
          && mesh->face_materials[2] == g && mesh->face_materials[3] == p
          && mesh->face_materials[4] == w);
    CHECK(wood->model == CG_MESH_MATERIAL_PHONG);
    CHECK(wood->base_color.r == 0.8f && wood->base_color.g == 0.6f && wood->base_color.b == 0.4f
          && wood->base_color.a == 0.75f);
    CHECK(wood->specular.r == 0.5f && wood->specular.g == 0.25f && wood->specular.b == 0.125f);
    CHECK(wood->shininess == 96 && wood->illum == 3 && wood->emissive.r == 0.5f);
    CHECK(wood->alpha_mode == CG_MESH_ALPHA_BLEND);
    CHECK_MSG(ends_with(wood->base_color_map.image_path, "/lib/wood grain.png"), "map_Kd '%s'",
              wood->base_color_map.image_path);
    CHECK(wood->base_color_map.encoding == CG_TEXTURE_SRGB);
    CHECK(wood->base_color_map.wrap_u == CG_TEXTURE_CLAMP
          && wood->base_color_map.wrap_v == CG_TEXTURE_CLAMP);
    /* -s 2 4 -o 0.5 0.25 in OBJ's space is scale (2, 4), offset (0.5, 1 - 4 - 0.25) in glTF's */
    CHECK(wood->base_color_map.scale[0] == 2 && wood->base_color_map.scale[1] == 4);
    CHECK(wood->base_color_map.offset[0] == 0.5 && wood->base_color_map.offset[1] == -3.25);
    CHECK(ends_with(wood->specular_map.image_path, "/lib/spec.png"));
    CHECK(ends_with(wood->alpha_map.image_path, "/lib/alpha.png")
          && wood->alpha_map.encoding == CG_TEXTURE_LINEAR);
    CHECK(ends_with(wood->bump_map.image_path, "/lib/bump.png") && wood->bump_map.amount == 0.3
          && wood->bump_map.encoding == CG_TEXTURE_LINEAR);
    CHECK(ends_with(wood->normal_map.image_path, "/lib/normals.png"));
    /* Tr is transparency; one Kd number is grey; a backslash path */
    CHECK_NEAR(glass->base_color.a, 0.1, 1e-6);
    CHECK(glass->base_color.r == 0.5f && glass->base_color.g == 0.5f
          && glass->base_color.b == 0.5f);
    CHECK_MSG(ends_with(glass->bump_map.image_path, "/lib/./bump.png"), "bump '%s'",
              glass->bump_map.image_path);
    /* a missing map: a note naming the file, and the colour stays */
    CHECK(plain->base_color_map.image_path == NULL && plain->illum == 1);
    CHECK_MSG(mesh->notes && strstr(mesh->notes, "materials.mtl:25: map_Kd file ")
                  && strstr(mesh->notes, "/lib/missing texture.png not found; material 'plain' "
                                         "keeps its colour"),
              "notes '%s'", mesh->notes ? mesh->notes : "");
    CHECK_MSG(!strstr(mesh->notes ? mesh->notes : "", "missing.png"),
              "a material no face uses is not read");
    /* face colours: Kd where given, none elsewhere */
    CHECK(mesh->face_colors && mesh->face_colors[1].r == 0.8f && mesh->face_colors[1].a == 1
          && mesh->face_colors[0].a == 0 && mesh->face_colors[3].a == 0);
    cg_mesh_free(mesh);
}

static void missing_and_broken(void)
{
    write_file("nolib.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    cg_error err;
    cg_mesh *mesh = load("nolib.obj", &err);
    CHECK_MSG(mesh != NULL, "%s", err.message);
    if (mesh) {
        CHECK(mesh->material_count == 1 && strcmp(mesh->materials[0].name, "a") == 0);
        CHECK(mesh->materials[0].base_color.r == 1 && mesh->materials[0].base_color.a == 1);
        CHECK_MSG(mesh->notes
                      && strstr(mesh->notes, "nolib.obj: material library nowhere.mtl "
                                             "not found"),
                  "notes '%s'", mesh->notes ? mesh->notes : "");
    }
    cg_mesh_free(mesh);
    static const struct {
        const char *mtl, *says;
    } broken[] = {
        {"newmtl a\nNs many\n", "bad.mtl:2: expected a number after Ns, got 'many'"},
        {"newmtl a\nKd 1 x 0\n", "bad.mtl:2: expected a green value, got 'x'"},
        {"newmtl a\nd\n", "bad.mtl:2: expected an opacity in [0, 1]"},
        {"newmtl a\nillum 99\n", "bad.mtl:2: expected an illumination model 0 to 10"},
        {"newmtl a\nmap_Kd -bm\n", "bad.mtl:2: expected a number after the option"},
        {"newmtl a\nmap_Kd -s 2\n", "bad.mtl:2: expected a texture file name"},
        {"newmtl a\nmap_Kd -o\n", "bad.mtl:2: expected 1 to 3 numbers after the option"},
    };
    write_file("bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    for (size_t i = 0; i < sizeof broken / sizeof broken[0]; i++) {
        write_file("bad.mtl", broken[i].mtl);
        mesh = load("bad.obj", &err);
        CHECK_MSG(!mesh && err.status == CG_EFORMAT && strstr(err.message, broken[i].says),
                  "case %zu: '%s' should say '%s'", i, err.message, broken[i].says);
        cg_mesh_free(mesh);
    }
    /* the same OBJ from memory reads no library: materials keep the defaults */
    const char *obj = "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x y\nf 1 2 3\n";
    CHECK(cg_mesh_load_memory(obj, strlen(obj), "m.obj", CG_MESH_FORMAT_OBJ, &mesh, &err) == CG_OK);
    CHECK(mesh && mesh->material_count == 1 && strcmp(mesh->materials[0].name, "x y") == 0
          && mesh->face_materials[0] == 0 && !mesh->notes);
    cg_mesh_free(mesh);
}

static void remove_all(const char *path)
{
    char command[300];
    snprintf(command, sizeof command, "rm -rf '%s'", path);
    if (system(command) != 0)
        fprintf(stderr, "could not remove %s\n", path);
}

int main(int argc, char **argv)
{
    snprintf(dir, sizeof dir, "/tmp/cg_mtl_XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    char lib[128];
    snprintf(lib, sizeof lib, "%s/lib", dir);
    mkdir(lib, 0755);
    check_start(argc, argv);
    CHECK_GROUP(statements);
    CHECK_GROUP(missing_and_broken);
    remove_all(dir);
    return check_finish();
}
