/* Bad input the mesh readers must refuse, with the file, the line or byte
 * and the value: a NaN or infinite coordinate anywhere in random meshes of
 * every format (and in cg_mesh_validate), negative list lengths of signed
 * PLY count types, and formats cg does not read (glTF, FBX, ...), which must
 * be named instead of being parsed as OBJ. */
#include "cg.h"
#include "check.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- a growing text ------------------------------------------------------ */

typedef struct text {
    char *bytes;
    size_t size, capacity;
} text;

static void put(text *t, const void *bytes, size_t n)
{
    if (t->size + n + 1 > t->capacity) {
        t->capacity = (t->size + n + 1) * 2;
        t->bytes = realloc(t->bytes, t->capacity);
        if (!t->bytes)
            abort();
    }
    memcpy(t->bytes + t->size, bytes, n);
    t->size += n;
    t->bytes[t->size] = '\0';
}

static void putf(text *t, const char *format, ...)
{
    char line[512];
    va_list args;
    va_start(args, format);
    int n = vsnprintf(line, sizeof line, format, args);
    va_end(args);
    put(t, line, (size_t)n);
}

static void put_float(text *t, float f, int big)
{
    unsigned char b[4];
    uint32_t bits;
    memcpy(&bits, &f, 4);
    for (int i = 0; i < 4; i++)
        b[big ? 3 - i : i] = (unsigned char)(bits >> (8 * i));
    put(t, b, 4);
}

/* ---- the bad values -------------------------------------------------------- */

/* How each bad value is written in text and what the message shows. */
static const struct {
    const char *written;
    float binary;
    const char *shown;
} bad_values[] = {
    {"nan", NAN, "nan"},         {"NaN", NAN, "nan"},        {"inf", INFINITY, "inf"},
    {"-inf", -INFINITY, "-inf"}, {"1e999", INFINITY, "inf"}, {"-Infinity", -INFINITY, "-inf"},
};
enum { BAD_VALUES = sizeof bad_values / sizeof bad_values[0] };

static double random_coordinate(check_rng *rng)
{
    return (double)(int64_t)(check_rng_next(rng) % 2001) / 100.0 - 10.0;
}

/* Loads bytes and checks the failure: CG_EFORMAT, no mesh, and every
 * expected piece in the message. */
static void expect_refused(const text *t, const char *name, const char *where, char axis,
                           const char *shown)
{
    cg_mesh *m = NULL;
    cg_error err;
    cg_error_clear(&err);
    cg_status s = cg_mesh_load_memory(t->bytes, t->size, name, CG_MESH_FORMAT_AUTO, &m, &err);
    char value[64];
    snprintf(value, sizeof value, "got %c = %s", axis, shown);
    CHECK_MSG(s == CG_EFORMAT && m == NULL, "%s: status %d, expected CG_EFORMAT (%s)", name, s,
              err.message);
    CHECK_MSG(strstr(err.message, where) == err.message, "%s: '%s' does not start with '%s'", name,
              err.message, where);
    CHECK_MSG(strstr(err.message, value) != NULL, "%s: '%s' does not say '%s'", name, err.message,
              value);
    CHECK_MSG(strstr(err.message, "finite") != NULL, "%s: '%s'", name, err.message);
    cg_mesh_free(m);
}

static void expect_loads(const text *t, const char *name)
{
    cg_mesh *m = NULL;
    cg_error err;
    cg_status s = cg_mesh_load_memory(t->bytes, t->size, name, CG_MESH_FORMAT_AUTO, &m, &err);
    CHECK_MSG(s == CG_OK, "%s: %s", name, err.message);
    cg_mesh_free(m);
}

/* One random mesh of n vertices (a multiple of 3) in a text format, the bad
 * value (or none, bad < 0) at coordinate `axis` of vertex `at`.  Returns the
 * line of that vertex. */
enum text_format { TEXT_OBJ, TEXT_OFF, TEXT_PLY, TEXT_STL };

static size_t write_text_mesh(text *t, enum text_format format, check_rng *rng, int n, int at,
                              int axis, int bad)
{
    size_t line = 0, bad_line = 0;
    if (format == TEXT_OFF) {
        putf(t, "OFF\n%d %d 0\n", n, n / 3);
        line = 2;
    } else if (format == TEXT_PLY) {
        putf(t,
             "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
             "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
             "end_header\n",
             n, n / 3);
        line = 9;
    } else if (format == TEXT_STL) {
        putf(t, "solid random\n");
        line = 1;
    }
    for (int v = 0; v < n; v++) {
        if (format == TEXT_STL && v % 3 == 0) {
            putf(t, "facet normal 0 0 1\nouter loop\n");
            line += 2;
        }
        putf(t, "%s", format == TEXT_OBJ ? "v " : format == TEXT_STL ? "  vertex " : "");
        for (int k = 0; k < 3; k++) {
            if (v == at && k == axis && bad >= 0)
                putf(t, "%s%s", bad_values[bad].written, k < 2 ? " " : "");
            else
                putf(t, "%.2f%s", random_coordinate(rng), k < 2 ? " " : "");
        }
        putf(t, "\n");
        line++;
        if (v == at)
            bad_line = line;
        if (format == TEXT_STL && v % 3 == 2) {
            putf(t, "endloop\nendfacet\n");
            line += 2;
        }
    }
    for (int f = 0; f < n / 3 && format != TEXT_STL; f++) {
        if (format == TEXT_OBJ)
            putf(t, "f %d %d %d\n", 3 * f + 1, 3 * f + 2, 3 * f + 3);
        else
            putf(t, "3 %d %d %d\n", 3 * f, 3 * f + 1, 3 * f + 2);
    }
    if (format == TEXT_STL)
        putf(t, "endsolid random\n");
    return bad_line;
}

static void test_text_formats(void)
{
    static const char *const names[] = {"random.obj", "random.off", "random.ply", "random.stl"};
    check_rng rng = {0x5eed0001};
    for (int round = 0; round < 400; round++) {
        enum text_format format = (enum text_format)(round % 4);
        int n = 3 * (1 + (int)(check_rng_next(&rng) % 20));
        int at = (int)(check_rng_next(&rng) % (uint64_t)n);
        int axis = (int)(check_rng_next(&rng) % 3);
        int bad = (int)(check_rng_next(&rng) % BAD_VALUES);
        text t = {0};
        check_rng start = rng;
        size_t line = write_text_mesh(&t, format, &rng, n, at, axis, bad);
        char where[64];
        snprintf(where, sizeof where, "%s:%zu: ", names[format], line);
        expect_refused(&t, names[format], where, "xyz"[axis], bad_values[bad].shown);
        /* the same mesh without the bad value loads */
        t.size = 0;
        write_text_mesh(&t, format, &start, n, at, axis, -1);
        expect_loads(&t, names[format]);
        free(t.bytes);
    }
}

/* Binary PLY (float or double coordinates, either byte order, a normal after
 * the position) and binary STL with one bad coordinate. */
static void test_binary_formats(void)
{
    check_rng rng = {0x5eed0002};
    for (int round = 0; round < 300; round++) {
        int n = 3 * (1 + (int)(check_rng_next(&rng) % 20));
        int at = (int)(check_rng_next(&rng) % (uint64_t)n);
        int axis = (int)(check_rng_next(&rng) % 3);
        int bad = (int)(check_rng_next(&rng) % BAD_VALUES);
        int big = round % 2;
        text t = {0};
        char where[64];
        if (round % 3 < 2) {
            putf(&t,
                 "ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty float x\n"
                 "property float y\nproperty float z\nproperty float nx\nelement face %d\n"
                 "property list uchar int vertex_indices\nend_header\n",
                 big ? "big" : "little", n, n / 3);
            size_t body = t.size;
            for (int v = 0; v < n; v++) {
                for (int k = 0; k < 3; k++)
                    put_float(&t,
                              v == at && k == axis ? bad_values[bad].binary
                                                   : (float)random_coordinate(&rng),
                              big);
                put_float(&t, v % 2 ? NAN : 0.0f, big); /* a NaN normal is kept */
            }
            for (int f = 0; f < n / 3; f++) {
                unsigned char three = 3;
                put(&t, &three, 1);
                for (int k = 0; k < 3; k++) {
                    uint32_t i = (uint32_t)(3 * f + k);
                    unsigned char b[4];
                    for (int j = 0; j < 4; j++)
                        b[big ? 3 - j : j] = (unsigned char)(i >> (8 * j));
                    put(&t, b, 4);
                }
            }
            snprintf(where, sizeof where, "random.ply: byte %zu: ", body + (size_t)at * 16);
            expect_refused(&t, "random.ply", where, "xyz"[axis], bad_values[bad].shown);
            char item[32];
            snprintf(item, sizeof item, "(vertex %d)", at);
            cg_mesh *m = NULL;
            cg_error err;
            cg_mesh_load_memory(t.bytes, t.size, "random.ply", CG_MESH_FORMAT_AUTO, &m, &err);
            CHECK_MSG(strstr(err.message, item) != NULL, "'%s' does not say '%s'", err.message,
                      item);
            cg_mesh_free(m);
        } else {
            unsigned char header[84] = {0};
            memcpy(header, "binary", 6);
            header[80] = (unsigned char)(n / 3);
            put(&t, header, 84);
            for (int f = 0; f < n / 3; f++) {
                for (int k = 0; k < 3; k++)
                    put_float(&t, 0.0f, 0); /* normal */
                for (int c = 0; c < 3; c++)
                    for (int k = 0; k < 3; k++)
                        put_float(&t,
                                  3 * f + c == at && k == axis ? bad_values[bad].binary
                                                               : (float)random_coordinate(&rng),
                                  0);
                put(&t, "\0\0", 2);
            }
            snprintf(where, sizeof where,
                     "random.stl: byte %d: ", 84 + 50 * (at / 3) + 12 + 12 * (at % 3));
            expect_refused(&t, "random.stl", where, "xyz"[axis], bad_values[bad].shown);
        }
        free(t.bytes);
    }
}

/* cg_mesh_validate refuses a mesh built in memory with a bad position and
 * names the vertex; the same mesh with finite positions validates. */
static void test_validate(void)
{
    check_rng rng = {0x5eed0003};
    for (int round = 0; round < 200; round++) {
        size_t n = 3 + check_rng_next(&rng) % 30;
        cg_mesh *m = NULL;
        if (cg_mesh_create(&m, n, 1, 3, 0) != CG_OK) {
            CHECK(0);
            return;
        }
        for (size_t v = 0; v < n; v++)
            m->positions[v] = cg_vec3_make(random_coordinate(&rng), random_coordinate(&rng),
                                           random_coordinate(&rng));
        m->face_offsets[1] = 3;
        m->face_indices[0] = 0;
        m->face_indices[1] = 1;
        m->face_indices[2] = 2;
        cg_error err;
        CHECK_MSG(cg_mesh_validate(m, &err) == CG_OK, "%s", err.message);
        size_t at = check_rng_next(&rng) % n;
        int axis = (int)(check_rng_next(&rng) % 3);
        double bad = round % 3 == 0 ? NAN : round % 3 == 1 ? INFINITY : -INFINITY;
        double *p = axis == 0   ? &m->positions[at].x
                    : axis == 1 ? &m->positions[at].y
                                : &m->positions[at].z;
        *p = bad;
        char expected[64];
        snprintf(expected, sizeof expected, "vertex %zu: expected finite coordinates, got %c = %s",
                 at, "xyz"[axis],
                 round % 3 == 0   ? "nan"
                 : round % 3 == 1 ? "inf"
                                  : "-inf");
        CHECK(cg_mesh_validate(m, &err) == CG_EFORMAT);
        CHECK_MSG(strstr(err.message, expected) != NULL, "'%s' does not say '%s'", err.message,
                  expected);
        cg_mesh_free(m);
    }
}

/* A negative list length of a signed count type is an error (reading it as
 * a count was undefined behaviour), in ASCII and binary PLY. */
static void test_negative_list_lengths(void)
{
    static const char *const count_types[] = {"char", "int8", "short", "int16", "int", "int32"};
    for (int c = 0; c < 6; c++) {
        for (int length = -3; length <= -1; length++) {
            text t = {0};
            putf(&t,
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                 "property float y\nproperty float z\nelement face 1\n"
                 "property list %s int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                 "%d 0 1 2\n",
                 count_types[c], length);
            cg_mesh *m = NULL;
            cg_error err;
            cg_status s = cg_mesh_load_memory(t.bytes, t.size, "neg.ply", CG_MESH_FORMAT_AUTO, &m,
                                              &err);
            char expected[96];
            snprintf(expected, sizeof expected,
                     "neg.ply:13: expected a list length of 0 or more in face 0, got %d", length);
            CHECK_MSG(s == CG_EFORMAT && strstr(err.message, expected) == err.message, "%s %d: %s",
                      count_types[c], length, err.message);
            cg_mesh_free(m);
            /* a list the face does not use (an extra property) too */
            t.size = 0;
            putf(&t,
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                 "property float y\nproperty float z\nproperty list %s float extra\n"
                 "end_header\n0 0 0 0\n1 0 0 %d\n0 1 0 0\n",
                 count_types[c], length);
            s = cg_mesh_load_memory(t.bytes, t.size, "neg2.ply", CG_MESH_FORMAT_AUTO, &m, &err);
            CHECK_MSG(s == CG_EFORMAT && m == NULL, "%s", err.message);
            cg_mesh_free(m);
            free(t.bytes);
        }
    }
}

/* Formats cg does not read are named, by their bytes or by their name, with
 * CG_EUNSUPPORTED, whatever reader they resemble. */
static void test_foreign_formats(void)
{
    static const struct {
        const char *bytes;
        size_t size;
        const char *name;
        const char *expected;
    } cases[] = {
        {"Kaydara FBX Binary  \0\x1a\0", 23, "model.bin", "an FBX file (.fbx)"},
        {"; FBX 7.4.0 project file\n", 25, "a.txt", "an FBX file (.fbx)"},
        {"v 0 0 0\n", 8, "model.FBX", "an FBX file (.fbx)"},
        {"\x4d\x4d\x0a\0\0\0\x02\0\x04\0", 10, "box", "a 3D Studio file (.3ds)"},
        {"x", 1, "box.3ds", "a 3D Studio file (.3ds)"},
        {"<?xml version=\"1.0\"?>\n<COLLADA>", 31, "scene", "a COLLADA file (.dae)"},
        {"<a/>", 4, "scene.dae.gz", "a COLLADA file (.dae)"},
        {"BLENDER-v300", 12, "scene", "a Blender file (.blend)"},
        {"# vtk DataFile Version 3.0\n", 27, "mesh", "a VTK file (.vtk)"},
        {"#usda 1.0\n", 10, "mesh", "a USD file (.usda)"},
        {"#VRML V2.0 utf8\n", 16, "mesh", "a VRML file (.wrl)"},
        {"PK\3\4", 4, "mesh", "a ZIP archive"},
        {"FORM\0\0\0\4LWO2", 12, "mesh", "a LightWave object (.lwo)"},
        {"AC3Db\nMATERIAL", 14, "mesh", "an AC3D file (.ac)"},
        {"IDPO\6\0\0\0", 8, "mesh", "a Quake model (.mdl)"},
        {"*3DSMAX_ASCIIEXPORT 200\n", 24, "mesh", "an ASCII Scene Export file (.ase)"},
        {"<?xml version=\"1.0\"?>\n<mesh xmlns=\"irrmesh\">", 44, "m",
         "an Irrlicht mesh (.irrmesh)"},
        /* NFF starts like OBJ ("v" then a viewpoint): its name tells */
        {"v\nfrom 0 0 5\nat 0 0 0\n", 22, "scene.nff", "a Neutral File Format file (.nff)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cg_mesh *m = NULL;
        cg_error err;
        cg_status s = cg_mesh_load_memory(cases[i].bytes, cases[i].size, cases[i].name,
                                          CG_MESH_FORMAT_AUTO, &m, &err);
        CHECK_MSG(s == CG_EUNSUPPORTED && m == NULL, "%s: status %d: %s", cases[i].name, s,
                  err.message);
        CHECK_MSG(strstr(err.message, cases[i].expected) != NULL
                      && strstr(err.message, "does not read") != NULL
                      && strstr(err.message, cases[i].name) == err.message,
                  "%s: '%s' does not name %s", cases[i].name, err.message, cases[i].expected);
        cg_mesh_free(m);
    }
    /* a cg format's magic wins over a foreign name; an asked-for format is read as asked */
    cg_mesh *m = NULL;
    cg_error err;
    const char *off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    CHECK_MSG(cg_mesh_load_memory(off, strlen(off), "mesh.glb", CG_MESH_FORMAT_AUTO, &m, &err)
                  == CG_OK,
              "%s", err.message);
    cg_mesh_free(m);
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK_MSG(cg_mesh_load_memory(obj, strlen(obj), "mesh.fbx", CG_MESH_FORMAT_OBJ, &m, &err)
                  == CG_OK,
              "%s", err.message);
    cg_mesh_free(m);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(test_text_formats);
    CHECK_GROUP(test_binary_formats);
    CHECK_GROUP(test_validate);
    CHECK_GROUP(test_negative_list_lengths);
    CHECK_GROUP(test_foreign_formats);
    return check_finish();
}
