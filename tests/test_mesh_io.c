/* Mesh files: every reader on small fixtures written here, every malformed
 * case with its message, save/load round trips, exact number parsing, and
 * the real meshes in data/meshes. */
#include "cg.h"
#include "check.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

static cg_mesh *load_text(const char *text, const char *name, cg_mesh_format format,
                          cg_status *status, cg_error *err)
{
    cg_mesh *m = NULL;
    cg_error e;
    if (!err)
        err = &e;
    cg_error_clear(err);
    *status = cg_mesh_load_memory(text, strlen(text), name, format, &m, err);
    return m;
}

/* Loads text that must be valid; checks the mesh validates. */
static cg_mesh *load_ok(const char *text, const char *name)
{
    cg_status s;
    cg_error err;
    cg_mesh *m = load_text(text, name, CG_MESH_FORMAT_AUTO, &s, &err);
    CHECK_MSG(s == CG_OK && m, "%s: %s", name, err.message);
    if (m) {
        CHECK_MSG(cg_mesh_validate(m, &err) == CG_OK, "%s: %s", name, err.message);
    }
    return m;
}

static int face_is(const cg_mesh *m, size_t f, const uint32_t *expected, uint32_t n)
{
    if (f >= m->face_count || cg_mesh_face_size(m, f) != n)
        return 0;
    for (uint32_t k = 0; k < n; k++)
        if (m->face_indices[m->face_offsets[f] + k] != expected[k])
            return 0;
    return 1;
}

static char temp_dir[256];

static void make_temp_dir(void)
{
    snprintf(temp_dir, sizeof temp_dir, "/tmp/cg-mesh-io-XXXXXX");
    if (!mkdtemp(temp_dir)) {
        fprintf(stderr, "cannot make a temporary directory: %s\n", strerror(errno));
        exit(1);
    }
}

static void write_file(const char *name, const void *bytes, size_t size)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", temp_dir, name);
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        fwrite(bytes, 1, size, f);
        fclose(f);
    }
}

static void remove_temp_dir(void)
{
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", temp_dir);
    if (system(command) != 0)
        fprintf(stderr, "could not remove %s\n", temp_dir);
}

/* ---- OBJ ------------------------------------------------------------------ */

static void test_obj(void)
{
    cg_mesh *m = load_ok("# a square and a triangle\n"
                         "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\r\n"
                         "g square\nf 1 2 3 4\n"
                         "o tri\ns off\nf -4 -3 -2\n",
                         "square.obj");
    if (m) {
        CHECK_EQ_INT(m->vertex_count, 4);
        CHECK_EQ_INT(m->face_count, 2);
        uint32_t a[] = {0, 1, 2, 3}, b[] = {0, 1, 2};
        CHECK(face_is(m, 0, a, 4));
        CHECK(face_is(m, 1, b, 3));
        CHECK(m->normals == NULL && m->texcoords == NULL && m->colors == NULL);
        CHECK(m->positions[2].x == 1 && m->positions[2].y == 1 && m->positions[2].z == 0);
        cg_mesh_free(m);
    }
    /* v/vt/vn forms; each position used with one pair keeps its number */
    m = load_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n",
                "forms.obj");
    if (m) {
        CHECK_EQ_INT(m->vertex_count, 3);
        CHECK(m->normals && m->texcoords);
        if (m->normals && m->texcoords) {
            CHECK(m->normals[2].z == 1);
            CHECK(m->texcoords[1].x == 1 && m->texcoords[2].y == 1);
        }
        cg_mesh_free(m);
    }
    /* a position used with two normals becomes two vertices */
    m = load_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 -1\n"
                "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\nf 3//1 2//1 4//1\n",
                "split.obj");
    if (m) {
        CHECK_EQ_INT(m->vertex_count, 7); /* 2, 3 and 4 each meet a second normal */
        for (size_t f = 0; f < m->face_count; f++)
            for (uint32_t k = m->face_offsets[f]; k < m->face_offsets[f + 1]; k++) {
                uint32_t v = m->face_indices[k];
                double expected = f == 1 ? -1 : 1;
                CHECK(m->normals[v].z == expected);
            }
        CHECK(m->positions[m->face_indices[3]].x == 1 && m->positions[m->face_indices[3]].y == 0);
        cg_mesh_free(m);
    }
    /* v/vt form, v x y z r g b colours, a pentagon, no final line end */
    m = load_ok("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\nv -1 0 0 0 0 0\n"
                "vt 0.5 0.5\nf 1/1 2/1 3/1 4/1 5/1",
                "pentagon.obj");
    if (m) {
        CHECK_EQ_INT(m->face_count, 1);
        CHECK_EQ_INT(cg_mesh_face_size(m, 0), 5);
        CHECK(m->colors != NULL);
        if (m->colors)
            CHECK(m->colors[1].g == 1 && m->colors[1].r == 0);
        cg_mesh_free(m);
    }
    /* forward references are allowed when the vertex comes later */
    m = load_ok("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "forward.obj");
    cg_mesh_free(m);
    /* points and lines only: vertices, no faces */
    m = load_ok("v 0 0 0\nv 1 0 0\nl 1 2\np 1\n", "lines.obj");
    if (m)
        CHECK(m->vertex_count == 2 && m->face_count == 0);
    cg_mesh_free(m);
}

static void test_obj_materials(void)
{
    const char *mtl = "# two materials\nnewmtl red\nKa 0 0 0\nKd 1 0 0\n\n"
                      "newmtl grey one\nKd 0.5\nnewmtl unused\nKd 0 0 1\n";
    const char *obj = "mtllib cube.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                      "f 1 2 3\nusemtl red\nf 2 4 3\nusemtl grey one\nf 1 2 4\n"
                      "usemtl nowhere\nf 1 3 4\n";
    write_file("cube.mtl", mtl, strlen(mtl));
    write_file("cube.obj", obj, strlen(obj));
    write_file("nolib.obj", obj, strlen(obj));
    char path[512];
    snprintf(path, sizeof path, "%s/cube.obj", temp_dir);
    cg_mesh *m = NULL;
    cg_error err;
    CHECK_MSG(cg_mesh_load(path, &m, &err) == CG_OK, "%s", err.message);
    if (m) {
        CHECK(m->face_colors != NULL);
        if (m->face_colors) {
            CHECK(m->face_colors[0].a == 0);                             /* no material */
            CHECK(m->face_colors[1].r == 1 && m->face_colors[1].g == 0); /* red */
            CHECK(m->face_colors[2].r == 0.5f && m->face_colors[2].b == 0.5f);
            CHECK(m->face_colors[3].a == 0); /* unknown material */
        }
        cg_mesh_free(m);
    }
    /* the same file beside no library: loads, no colours */
    unlink(path);
    snprintf(path, sizeof path, "%s/cube.mtl", temp_dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/nolib.obj", temp_dir);
    CHECK_MSG(cg_mesh_load(path, &m, &err) == CG_OK, "%s", err.message);
    if (m)
        CHECK(m->face_colors == NULL && m->face_count == 4);
    cg_mesh_free(m);
    /* several libraries on one mtllib line, and a library name with a blank */
    const char *a = "newmtl a\nKd 0 1 0\n", *b = "newmtl b\nKd 0 0 1\n";
    write_file("one.mtl", a, strlen(a));
    write_file("two words.mtl", b, strlen(b));
    const char *two = "mtllib one.mtl missing.mtl\nmtllib two words.mtl\nv 0 0 0\nv 1 0 0\n"
                      "v 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\n";
    write_file("two.obj", two, strlen(two));
    snprintf(path, sizeof path, "%s/two.obj", temp_dir);
    CHECK_MSG(cg_mesh_load(path, &m, &err) == CG_OK, "%s", err.message);
    if (m) {
        CHECK(m->face_colors && m->face_colors[0].g == 1 && m->face_colors[1].b == 1);
        cg_mesh_free(m);
    }
    /* a malformed Kd in a library is an error naming the library's line */
    const char *bad = "newmtl red\nKd 1 zero 0\n";
    write_file("bad.mtl", bad, strlen(bad));
    const char *uses = "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    write_file("bad.obj", uses, strlen(uses));
    snprintf(path, sizeof path, "%s/bad.obj", temp_dir);
    CHECK(cg_mesh_load(path, &m, &err) == CG_EFORMAT && m == NULL);
    CHECK_MSG(strstr(err.message, "bad.mtl:2:") != NULL, "%s", err.message);
}

/* ---- OFF ------------------------------------------------------------------ */

static void test_off(void)
{
    cg_mesh *m = load_ok("OFF\n# a tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                         "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3 255 0 0\n",
                         "tet.off");
    if (m) {
        CHECK_EQ_INT(m->vertex_count, 4);
        CHECK_EQ_INT(m->face_count, 4);
        uint32_t f3[] = {1, 2, 3};
        CHECK(face_is(m, 3, f3, 3));
        CHECK(m->face_colors && m->face_colors[3].r == 1 && m->face_colors[3].g == 0
              && m->face_colors[0].r == 1 && m->face_colors[0].g == 1);
        cg_mesh_free(m);
    }
    m = load_ok("COFF 3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 0.5\n0 1 0 0 0 1 1\n3 0 1 2\n", "c.off");
    if (m) {
        CHECK(m->colors && m->colors[1].g == 1 && m->colors[1].a == 0.5f);
        cg_mesh_free(m);
    }
    m = load_ok("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", "n.off");
    if (m) {
        CHECK(m->normals && m->normals[2].z == 1);
        cg_mesh_free(m);
    }
    m = load_ok("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n", "st.off");
    if (m) {
        CHECK(m->texcoords && m->texcoords[2].y == 1);
        cg_mesh_free(m);
    }
}

/* ---- PLY ------------------------------------------------------------------ */

static void put_bytes(unsigned char **p, const void *v, size_t n, int big)
{
    const unsigned char *b = v;
    for (size_t i = 0; i < n; i++)
        (*p)[i] = big ? b[n - 1 - i] : b[i];
    *p += n;
}

/* A binary PLY with properties in an unusual order, an extra element and
 * extra properties, in either byte order. */
static size_t binary_ply(unsigned char *out, int big)
{
    char header[1024];
    int n = snprintf(header, sizeof header,
                     "ply\nformat %s 1.0\ncomment test\nelement vertex 4\n"
                     "property uchar red\nproperty double z\nproperty float confidence\n"
                     "property float y\nproperty short x\n"
                     "element material 1\nproperty list uchar float values\n"
                     "element face 2\nproperty int flags\n"
                     "property list ushort uint vertex_indices\nproperty uchar blue\n"
                     "end_header\n",
                     big ? "binary_big_endian" : "binary_little_endian");
    memcpy(out, header, (size_t)n);
    unsigned char *p = out + n;
    for (int v = 0; v < 4; v++) {
        unsigned char red = (unsigned char)(v * 60);
        double z = 0.25 * v;
        float confidence = 1, y = (float)(v / 2);
        int16_t x = (int16_t)(v % 2 ? -3 : 5);
        put_bytes(&p, &red, 1, big);
        put_bytes(&p, &z, 8, big);
        put_bytes(&p, &confidence, 4, big);
        put_bytes(&p, &y, 4, big);
        put_bytes(&p, &x, 2, big);
    }
    unsigned char count = 2;
    float values[2] = {1, 2};
    put_bytes(&p, &count, 1, big);
    put_bytes(&p, &values[0], 4, big);
    put_bytes(&p, &values[1], 4, big);
    int32_t flags = 7;
    uint16_t corners[2] = {3, 3};
    uint32_t faces[2][4] = {{0, 1, 2, 0}, {1, 3, 2, 0}};
    unsigned char blue[2] = {255, 0};
    put_bytes(&p, &flags, 4, big);
    put_bytes(&p, &corners[0], 2, big);
    for (int k = 0; k < 3; k++)
        put_bytes(&p, &faces[0][k], 4, big);
    put_bytes(&p, &blue[0], 1, big);
    put_bytes(&p, &flags, 4, big);
    put_bytes(&p, &corners[1], 2, big);
    for (int k = 0; k < 3; k++)
        put_bytes(&p, &faces[1][k], 4, big);
    put_bytes(&p, &blue[1], 1, big);
    return (size_t)(p - out);
}

static void check_binary_ply_mesh(const cg_mesh *m)
{
    CHECK_EQ_INT(m->vertex_count, 4);
    CHECK_EQ_INT(m->face_count, 2);
    CHECK(m->positions[1].x == -3 && m->positions[3].y == 1 && m->positions[2].z == 0.5);
    CHECK(m->colors != NULL && m->face_colors != NULL);
    if (m->colors)
        CHECK(m->colors[0].r == 0 && m->colors[1].r == cg_srgb8_to_linear(60));
    if (m->face_colors)
        CHECK(m->face_colors[0].b == 1 && m->face_colors[1].b == 0 && m->face_colors[1].r == 1);
    uint32_t f1[] = {1, 3, 2};
    CHECK(face_is(m, 1, f1, 3));
}

static void test_ply(void)
{
    cg_mesh *m = load_ok("ply\nformat ascii 1.0\ncomment unit square\nobj_info x\n"
                         "element vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nproperty float nx\nproperty float ny\n"
                         "property float nz\nproperty float s\nproperty float t\n"
                         "element face 1\nproperty list uchar int vertex_index\nend_header\n"
                         "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
                         "0 1 0 0 0 1 0 1\n4 0 1 2 3\n",
                         "square.ply");
    if (m) {
        uint32_t f[] = {0, 1, 2, 3};
        CHECK(face_is(m, 0, f, 4));
        CHECK(m->normals && m->normals[3].z == 1);
        CHECK(m->texcoords && m->texcoords[2].x == 1 && m->texcoords[2].y == 1);
        cg_mesh_free(m);
    }
    unsigned char bytes[2048];
    for (int big = 0; big < 2; big++) {
        size_t n = binary_ply(bytes, big);
        cg_error err;
        m = NULL;
        CHECK_MSG(cg_mesh_load_memory(bytes, n, "b.ply", CG_MESH_FORMAT_AUTO, &m, &err) == CG_OK,
                  "%s", err.message);
        if (m) {
            check_binary_ply_mesh(m);
            cg_mesh_free(m);
        }
        /* every truncation is an error naming a byte offset, never a crash */
        size_t header = (size_t)(strstr((char *)bytes, "end_header\n") - (char *)bytes) + 11;
        for (size_t cut = 0; cut < n; cut++) {
            cg_status s = cg_mesh_load_memory(bytes, cut, "b.ply", CG_MESH_FORMAT_PLY, &m, &err);
            CHECK_MSG(s != CG_OK && m == NULL, "truncated at %zu loads", cut);
            if (cut > header)
                CHECK_MSG(strstr(err.message, "byte ") != NULL, "%s", err.message);
        }
        /* an extra byte after the data is an error too */
        bytes[n] = 0;
        CHECK(cg_mesh_load_memory(bytes, n + 1, "b.ply", CG_MESH_FORMAT_PLY, &m, &err)
              == CG_EFORMAT);
    }
    /* a face property cg keeps no array for (alpha alone) is read past */
    m = load_ok("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "property uchar alpha\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n",
                "alpha.ply");
    if (m)
        CHECK(m->face_colors == NULL && m->face_count == 1);
    cg_mesh_free(m);
    /* a face element before the vertex element */
    m = load_ok("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar uint vertex_indices\n"
                "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                "end_header\n3 2 1 0\n0 0 0\n1 0 0\n0 1 0\n",
                "faces-first.ply");
    cg_mesh_free(m);
}

/* ---- STL ------------------------------------------------------------------ */

static size_t binary_stl(unsigned char *out, const char *header80)
{
    memset(out, 0, 84);
    memcpy(out, header80, strlen(header80));
    uint32_t n = 2;
    memcpy(out + 80, &n, 4);
    float tri[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (int t = 0; t < 2; t++) {
        memcpy(out + 84 + 50 * t, tri[t], 48);
        memset(out + 84 + 50 * t + 48, 0, 2);
    }
    /* -0 and +0 are the same vertex */
    float minus_zero = -0.0f;
    memcpy(out + 84 + 50 + 16, &minus_zero, 4); /* y of (1, 0, 0) */
    return 84 + 100;
}

static void test_stl(void)
{
    cg_mesh *m = load_ok("solid square\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                         "   vertex 1 0 0\n   vertex 1 1 0\n  endloop\n endfacet\n"
                         " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 1 0\n"
                         "   vertex 0 1 0\n  endloop\n endfacet\nendsolid square\n",
                         "square.stl");
    if (m) {
        CHECK_EQ_INT(m->vertex_count, 4);
        CHECK_EQ_INT(m->face_count, 2);
        uint32_t f[] = {0, 2, 3};
        CHECK(face_is(m, 1, f, 3));
        cg_mesh_free(m);
    }
    /* two solids in one file; the second one's triangle shares no vertex */
    m = load_ok("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                "vertex 0 1 0\nendloop\nendfacet\nendsolid a\nsolid b\nfacet normal 0 0 1\n"
                "outer loop\nvertex 5 0 0\nvertex 6 0 0\nvertex 5 1 0\nendloop\nendfacet\n"
                "endsolid b\n",
                "two.stl");
    if (m)
        CHECK(m->vertex_count == 6 && m->face_count == 2);
    cg_mesh_free(m);
    unsigned char bytes[256];
    const char *headers[] = {"binary", "solid but binary all the same"};
    for (int h = 0; h < 2; h++) {
        size_t n = binary_stl(bytes, headers[h]);
        cg_error err;
        m = NULL;
        CHECK_MSG(cg_mesh_load_memory(bytes, n, "b.stl", CG_MESH_FORMAT_AUTO, &m, &err) == CG_OK,
                  "%s", err.message);
        if (m) {
            CHECK_EQ_INT(m->vertex_count, 4);
            CHECK_EQ_INT(m->face_count, 2);
            uint32_t f[] = {1, 3, 2};
            CHECK(face_is(m, 1, f, 3));
            cg_mesh_free(m);
        }
        CHECK(cg_mesh_load_memory(bytes, n - 1, "b.stl", CG_MESH_FORMAT_STL, &m, &err) != CG_OK);
    }
}

/* ---- malformed input -------------------------------------------------------- */

typedef struct bad_case {
    const char *name;
    const char *text;
    cg_status status;
    const char *message; /* a piece the message must contain */
} bad_case;

static void test_malformed(void)
{
    static const bad_case cases[] = {
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", CG_EFORMAT,
         "a.obj:4: face refers to vertex 4"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", CG_EFORMAT,
         "a.obj:4: expected an index other than 0"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", CG_EFORMAT,
         "a.obj:4: relative index -4"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", CG_EFORMAT,
         "a.obj:4: expected a face of at least 3"},
        {"a.obj", "v 0 0 0\nv 1 0 x\n", CG_EFORMAT, "a.obj:2: expected a number"},
        {"a.obj", "v 0 0 0\nv 1 0 1.5.2\n", CG_EFORMAT, "a.obj:2: expected a number"},
        {"a.obj", "v 0 0 0\nv 1 0 1e\n", CG_EFORMAT, "a.obj:2:"},
        {"a.obj", "v 0 0\n", CG_EFORMAT, "a.obj:1: expected 3, 4 or 6 numbers"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", CG_EFORMAT,
         "a.obj:4: expected a texture coordinate index"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n", CG_EFORMAT,
         "a.obj:5: face refers to texture coordinate 2"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", CG_EFORMAT,
         "a.obj:4: face refers to normal 1"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n", CG_EFORMAT, "a.obj:4:"},
        {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", CG_EFORMAT, "a.obj:4:"},
        {"a.obj", "# nothing\n", CG_EFORMAT, "expected vertices"},
        {"a.obj", "", CG_EFORMAT, "a.obj: the file is empty"},
        {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", CG_EFORMAT,
         "a.off:5: expected 3 vertices, the file ends after 2"},
        {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", CG_EFORMAT,
         "a.off:6: face 0 refers to vertex 3"},
        {"a.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", CG_EFORMAT,
         "expected 2 faces, the file ends after 1"},
        {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", CG_EFORMAT,
         "a.off:7: expected the end of the file"},
        {"a.off", "OFF\n3 1 0\n0 0 0 5\n1 0 0\n0 1 0\n3 0 1 2\n", CG_EFORMAT,
         "a.off:3: expected 3 numbers"},
        {"a.off", "OFF\n-3 1 0\n", CG_EFORMAT, "a.off:2: expected the vertex count"},
        {"a.off", "OFF\n999999999999 1 0\n0 0 0\n", CG_ERANGE, "over cg_mesh's limit"},
        {"a.off", "OFF\n4000000000 1 0\n0 0 0\n", CG_EFORMAT,
         "expected 4000000000 vertices, the file ends after 1"},
        {"a.off", "4OFF\n1 0 0\n0 0 0 0\n", CG_EUNSUPPORTED, "4OFF"},
        {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", CG_EFORMAT,
         "a.off:6: expected a face's vertex count (3 or more)"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty "
         "float z\nend_header\n0 0 0\n1 1\n",
         CG_EFORMAT, "a.ply:10: expected a number of vertex 1, got the end of the file"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
         "float z\nend_header\n0 0 0\n5\n",
         CG_EFORMAT, "a.ply:9: expected the end of the file"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
         "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
         "0\n0 1 0\n3 0 1 3\n",
         CG_EFORMAT, "a.ply:13: face 0 refers to vertex 3"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
         "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
         "0\n0 1 0\n3 0 1 -1\n",
         CG_EFORMAT, "a.ply:13: face 0 refers to vertex -1"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
         "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
         "0\n0 1 0\n300 0 1 2\n",
         CG_EFORMAT,
         "a.ply:13: expected a list length (a whole number, 0 or more) of face 0, got '300'"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\nproperty float y\nproperty "
         "float z\nend_header\n0.5 0 0\n",
         CG_EFORMAT, "a.ply:8: expected an integer of vertex 0, got '0.5'"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float "
         "y\nend_header\n0 0\n",
         CG_EFORMAT, "properties x, y and z"},
        {"a.ply", "ply\nformat ascii 2.0\n", CG_EFORMAT, "a.ply:2: expected version 1.0"},
        {"a.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float32x x\n", CG_EFORMAT,
         "a.ply:4: expected a property type"},
        {"a.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", CG_EFORMAT,
         "expected 'end_header'"},
        {"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 99999999999999\nproperty float x\nproperty float "
         "y\nproperty float z\nend_header\n0 0 0\n",
         CG_EFORMAT, "a.ply:9: expected a number of vertex 1"},
        {"a.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float "
         "x\nproperty float y\nproperty float z\nend_header\n0123456789ab",
         CG_EFORMAT, "byte 124: the header says 4000000000 items of element 'vertex' (line 3)"},
        {"a.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float "
         "y\nproperty float z\nelement face 1\nproperty list uint int "
         "vertex_indices\nend_header\n0123456789ab\xff\xff\xff\xff",
         CG_EFORMAT, "byte 184: the file ends inside face 0"},
        {"a.ply", "ply\nformat ascii 1.0\nbogus line\n", CG_EFORMAT,
         "a.ply:3: expected a header keyword"},
        {"a.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 "
         "0\nendloop\nendfacet\nendsolid\n",
         CG_EFORMAT, "a.stl:6: expected another 'vertex'"},
        {"a.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 z 0\n",
         CG_EFORMAT, "a.stl:6: expected a vertex coordinate"},
        {"a.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 "
         "0\nendloop\n",
         CG_EFORMAT, "a.stl:8: expected 'endfacet', got the end of the file"},
        {"a.stl",
         "not an stl file at all, but long enough to have an 84-byte header................!!!!",
         CG_EFORMAT, "a.stl: byte 80: the header says"},
        {"a.xyz", "hello\n", CG_EFORMAT, "unknown mesh format"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cg_status s;
        cg_error err;
        cg_mesh *m = load_text(cases[i].text, cases[i].name, CG_MESH_FORMAT_AUTO, &s, &err);
        CHECK_MSG(s == cases[i].status && m == NULL, "case %zu (%s): status %d, expected %d: %s", i,
                  cases[i].name, (int)s, (int)cases[i].status, err.message);
        CHECK_MSG(strstr(err.message, cases[i].message) != NULL,
                  "case %zu: message '%s' lacks '%s'", i, err.message, cases[i].message);
        cg_mesh_free(m);
    }
}

/* ---- numbers ------------------------------------------------------------------ */

/* Numbers read by the OBJ reader equal strtod's, for many random forms. */
static void test_numbers(void)
{
    check_rng rng = {0x5eed1234abcdULL};
    enum { N = 20000 };
    char *text = malloc((size_t)N * 3 * 48 + 64);
    double *expected = malloc(sizeof(double) * N * 3);
    size_t at = 0;
    for (int i = 0; i < N * 3; i++) {
        char number[40];
        int form = (int)check_rng_int(&rng, 0, 7);
        double x = check_rng_range(&rng, -1, 1) * pow(10, (double)check_rng_int(&rng, -30, 30));
        switch (form) {
        case 0: snprintf(number, sizeof number, "%.17g", x); break;
        case 1: snprintf(number, sizeof number, "%.6f", x); break;
        case 2: snprintf(number, sizeof number, "%.9e", x); break;
        case 3:
            snprintf(number, sizeof number, "%lld",
                     (long long)check_rng_int(&rng, -99999999, 99999999));
            break;
        case 4: snprintf(number, sizeof number, "%.25g", x); break; /* beyond 19 digits */
        case 5: /* huge / denormal, finite (positions cg keeps are) */
            snprintf(number, sizeof number, "%.3g", isfinite(x * 1e280) ? x * 1e280 : x * 1e250);
            break;
        case 6: /* 16 to 19 significant digits, the long-double path */
            snprintf(number, sizeof number, "%.*e", (int)check_rng_int(&rng, 15, 18), x);
            break;
        default: /* a 19-digit integer with a decimal point somewhere */
            snprintf(number, sizeof number, "%llu",
                     (unsigned long long)(check_rng_next(&rng) >> 1));
            memmove(number + 4, number + 3, strlen(number + 3) + 1);
            number[3] = '.';
            break;
        }
        expected[i] = strtod(number, NULL);
        at += (size_t)sprintf(text + at,
                              i % 3 == 0   ? "v %s"
                              : i % 3 == 2 ? " %s\n"
                                           : " %s",
                              number);
    }
    text[at] = '\0';
    cg_status s;
    cg_error err;
    cg_mesh *m = load_text(text, "numbers.obj", CG_MESH_FORMAT_OBJ, &s, &err);
    CHECK_MSG(s == CG_OK, "%s", err.message);
    if (m) {
        int wrong = 0;
        for (int i = 0; i < N; i++) {
            const double *p = &m->positions[i].x;
            for (int k = 0; k < 3; k++)
                if (memcmp(&p[k], &expected[3 * i + k], sizeof(double)) != 0 && wrong++ < 5)
                    fprintf(stderr, "number %d: got %.17g, strtod %.17g\n", 3 * i + k, p[k],
                            expected[3 * i + k]);
        }
        CHECK_EQ_INT(wrong, 0);
        cg_mesh_free(m);
    }
    free(text);
    free(expected);
    /* special forms */
    m = load_text("v 1. .5 -0\nv +1e+2 1E-2 1E+300\nv -7 0.000000000000000000000000001 "
                  "123456789012345678901234567890\n",
                  "special.obj", CG_MESH_FORMAT_OBJ, &s, &err);
    CHECK_MSG(s == CG_OK, "%s", err.message);
    if (m) {
        CHECK(m->positions[0].x == 1 && m->positions[0].y == 0.5 && signbit(m->positions[0].z));
        CHECK(m->positions[1].x == 100 && m->positions[1].y == 0.01 && m->positions[1].z == 1e300);
        CHECK(m->positions[2].x == -7 && m->positions[2].y == 1e-27
              && m->positions[2].z == 123456789012345678901234567890.0);
        cg_mesh_free(m);
    }
    /* inf, nan and overflowing numbers are numbers, but not positions cg keeps */
    static const char *const nonfinite[] = {"inf", "-inf", "nan", "1e400", "-1E+999"};
    static const char *const shown[] = {"inf", "-inf", "nan", "inf", "-inf"};
    for (int i = 0; i < 5; i++) {
        char line[64], expected[96];
        snprintf(line, sizeof line, "v 1 2 3\nv 0 %s 0\n", nonfinite[i]);
        snprintf(expected, sizeof expected,
                 "special.obj:2: expected a finite vertex coordinate, got y = %s", shown[i]);
        m = load_text(line, "special.obj", CG_MESH_FORMAT_OBJ, &s, &err);
        CHECK_MSG(s == CG_EFORMAT && !m && strcmp(err.message, expected) == 0, "%s", err.message);
        cg_mesh_free(m);
    }
}

/* ---- round trips ------------------------------------------------------------ */

static cg_mesh *random_mesh(check_rng *rng, unsigned flags)
{
    size_t nv = (size_t)check_rng_int(rng, 3, 60), nf = (size_t)check_rng_int(rng, 1, 40);
    size_t corners = 0;
    uint32_t sizes[40];
    for (size_t f = 0; f < nf; f++) {
        sizes[f] = (uint32_t)check_rng_int(rng, 3, f == 0 ? 300 : 7);
        corners += sizes[f];
    }
    cg_mesh *m;
    if (cg_mesh_create(&m, nv, nf, corners, flags) != CG_OK)
        return NULL;
    for (size_t v = 0; v < nv; v++) {
        double scale = pow(10, (double)check_rng_int(rng, -12, 12));
        m->positions[v] = cg_vec3_make(check_rng_range(rng, -1, 1) * scale,
                                       check_rng_range(rng, -1, 1), check_rng_int(rng, -5, 5));
        if (m->normals)
            m->normals[v] = cg_vec3_normalize(
                cg_vec3_make(check_rng_range(rng, -1, 1), check_rng_range(rng, -1, 1), 0.5));
        if (m->texcoords)
            m->texcoords[v] = cg_vec2_make(check_rng_unit(rng), check_rng_unit(rng));
        if (m->colors) {
            cg_rgba8 c = {(uint8_t)check_rng_int(rng, 0, 255), (uint8_t)check_rng_int(rng, 0, 255),
                          (uint8_t)check_rng_int(rng, 0, 255), 255};
            m->colors[v] = cg_rgba8_to_linear(c);
        }
    }
    uint32_t at = 0;
    for (size_t f = 0; f < nf; f++) {
        m->face_offsets[f] = at;
        for (uint32_t k = 0; k < sizes[f]; k++)
            m->face_indices[at++] = (uint32_t)check_rng_int(rng, 0, (long long)nv - 1);
        if (m->face_colors) {
            cg_rgba8 c = {(uint8_t)check_rng_int(rng, 0, 255), (uint8_t)check_rng_int(rng, 0, 255),
                          (uint8_t)check_rng_int(rng, 0, 255), 255};
            m->face_colors[f] = cg_rgba8_to_linear(c);
        }
    }
    m->face_offsets[nf] = at;
    return m;
}

static int colors_match(cg_rgbaf a, cg_rgbaf b, double tolerance)
{
    return fabs(a.r - b.r) <= tolerance && fabs(a.g - b.g) <= tolerance
           && fabs(a.b - b.b) <= tolerance && fabs(a.a - b.a) <= tolerance;
}

static void compare_meshes(const cg_mesh *a, const cg_mesh *b, const char *what, int obj)
{
    CHECK_MSG(a->vertex_count == b->vertex_count && a->face_count == b->face_count,
              "%s: %zu/%zu vertices, %zu/%zu faces", what, a->vertex_count, b->vertex_count,
              a->face_count, b->face_count);
    if (a->vertex_count != b->vertex_count || a->face_count != b->face_count)
        return;
    CHECK_MSG(memcmp(a->positions, b->positions, a->vertex_count * sizeof(cg_vec3)) == 0,
              "%s: positions differ", what);
    CHECK_MSG(memcmp(a->face_offsets, b->face_offsets, (a->face_count + 1) * sizeof(uint32_t)) == 0,
              "%s: faces differ", what);
    CHECK_MSG(
        memcmp(a->face_indices, b->face_indices, a->face_offsets[a->face_count] * sizeof(uint32_t))
            == 0,
        "%s: face indices differ", what);
    CHECK_MSG(!a->normals == !b->normals && !a->texcoords == !b->texcoords
                  && !a->colors == !b->colors && !a->face_colors == !b->face_colors,
              "%s: optional arrays differ", what);
    double tolerance = obj ? 0 : 1e-6; /* PLY keeps normals and texcoords as float */
    for (size_t v = 0; v < a->vertex_count; v++) {
        if (a->normals && b->normals)
            CHECK(fabs(a->normals[v].x - b->normals[v].x) <= tolerance
                  && fabs(a->normals[v].z - b->normals[v].z) <= tolerance);
        if (a->texcoords && b->texcoords)
            CHECK(fabs(a->texcoords[v].y - b->texcoords[v].y) <= tolerance);
        if (a->colors && b->colors)
            CHECK(colors_match(a->colors[v], b->colors[v], obj ? 0 : 1e-6));
    }
    for (size_t f = 0; a->face_colors && b->face_colors && f < a->face_count; f++)
        CHECK(colors_match(a->face_colors[f], b->face_colors[f], 1e-6));
}

static void test_round_trips(void)
{
    check_rng rng = {42};
    static const struct {
        cg_mesh_format format;
        const char *file;
    } formats[] = {
        {CG_MESH_FORMAT_OBJ, "round.obj"},
        {CG_MESH_FORMAT_PLY_ASCII, "round-ascii.ply"},
        {CG_MESH_FORMAT_PLY_BINARY, "round-binary.ply"},
    };
    unsigned flag_sets[] = {0, CG_MESH_NORMALS, CG_MESH_TEXCOORDS | CG_MESH_NORMALS,
                            CG_MESH_COLORS | CG_MESH_FACE_COLORS,
                            CG_MESH_NORMALS | CG_MESH_TEXCOORDS | CG_MESH_COLORS
                                | CG_MESH_FACE_COLORS};
    for (int round = 0; round < 40; round++) {
        unsigned flags = flag_sets[round % 5];
        cg_mesh *m = random_mesh(&rng, flags);
        CHECK(m != NULL);
        if (!m)
            continue;
        for (size_t i = 0; i < 3; i++) {
            char path[512], what[128];
            snprintf(path, sizeof path, "%s/%s", temp_dir, formats[i].file);
            snprintf(what, sizeof what, "round %d %s", round, formats[i].file);
            cg_error err;
            cg_status s = cg_mesh_save(m, path, formats[i].format, &err);
            CHECK_MSG(s == CG_OK, "%s: %s", what, err.message);
            cg_mesh *back = NULL;
            s = cg_mesh_load(path, &back, &err);
            CHECK_MSG(s == CG_OK, "%s: %s", what, err.message);
            if (back) {
                compare_meshes(m, back, what, formats[i].format == CG_MESH_FORMAT_OBJ);
                cg_mesh_free(back);
            }
        }
        cg_mesh_free(m);
    }
    /* a new file gets the usual permissions (not mkstemp's 0600) */
    {
        mode_t mask = umask(022);
        umask(mask);
        char path[512];
        snprintf(path, sizeof path, "%s/round.obj", temp_dir);
        struct stat st;
        CHECK(stat(path, &st) == 0 && (st.st_mode & 0777) == (0666 & ~mask));
    }
    /* saving never leaves a partial file: an unwritable place fails cleanly, and a
     * mesh that does not validate is refused before anything is written */
    cg_mesh *m = random_mesh(&rng, 0);
    cg_error err;
    CHECK(cg_mesh_save(m, "/nonexistent-dir/x.obj", CG_MESH_FORMAT_AUTO, &err) == CG_EIO);
    CHECK(cg_mesh_save(m, "/tmp/x.fbx", CG_MESH_FORMAT_AUTO, &err) == CG_EUNSUPPORTED);
    char path[512];
    snprintf(path, sizeof path, "%s/invalid.ply", temp_dir);
    m->face_indices[0] = (uint32_t)m->vertex_count;
    CHECK(cg_mesh_save(m, path, CG_MESH_FORMAT_AUTO, &err) == CG_EFORMAT);
    CHECK(access(path, F_OK) != 0);
    cg_mesh_free(m);
}

/* ---- real meshes ---------------------------------------------------------------- */

static void test_real_meshes(void)
{
    static const struct {
        const char *file;
        size_t vertices, faces;
    } meshes[] = {
        {"bunny.obj", 1839, 3674},
        {"teapot.obj", 792, 992},
        {"dragon_vrip_res4.ply.gz", 5205, 11102},
    };
    for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/data/meshes/%s", CG_SOURCE_DIR, meshes[i].file);
        cg_mesh *m = NULL;
        cg_error err;
        CHECK_MSG(cg_mesh_load(path, &m, &err) == CG_OK, "%s", err.message);
        if (!m)
            continue;
        CHECK_EQ_INT(m->vertex_count, meshes[i].vertices);
        CHECK_EQ_INT(m->face_count, meshes[i].faces);
        CHECK(cg_mesh_validate(m, &err) == CG_OK);
        cg_vec3 lo, hi;
        CHECK(cg_mesh_bounds(m, &lo, &hi) == CG_OK && hi.x > lo.x && hi.y > lo.y);
        cg_mesh_free(m);
    }
    /* a truncated or corrupted gzip file is an error, not a crash */
    char path[512];
    snprintf(path, sizeof path, "%s/data/meshes/dragon_vrip_res4.ply.gz", CG_SOURCE_DIR);
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (!f)
        return;
    unsigned char *bytes = malloc(200000);
    size_t n = fread(bytes, 1, 200000, f);
    fclose(f);
    cg_mesh *m = NULL;
    cg_error err;
    CHECK(cg_mesh_load_memory(bytes, n / 2, "cut.ply.gz", CG_MESH_FORMAT_AUTO, &m, &err)
          == CG_EFORMAT);
    CHECK_MSG(strstr(err.message, "cut.ply.gz") != NULL, "%s", err.message);
    bytes[n / 3] ^= 0x55;
    CHECK(cg_mesh_load_memory(bytes, n, "bad.ply.gz", CG_MESH_FORMAT_AUTO, &m, &err) != CG_OK);
    CHECK(m == NULL);
    free(bytes);
}

/* bytes gzip-compressed into out; returns the compressed size. */
static size_t gzip_bytes(const void *bytes, size_t size, unsigned char *out, size_t room)
{
    z_stream z;
    memset(&z, 0, sizeof z);
    if (deflateInit2(&z, 9, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        return 0;
    z.next_in = (unsigned char *)(uintptr_t)bytes;
    z.avail_in = (uInt)size;
    z.next_out = out;
    z.avail_out = (uInt)room;
    int rc = deflate(&z, Z_FINISH);
    size_t n = room - z.avail_out;
    deflateEnd(&z);
    return rc == Z_STREAM_END ? n : 0;
}

static void test_gzip(void)
{
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    unsigned char packed[512], twice[1024], nested[1024];
    size_t n = gzip_bytes(obj, strlen(obj), packed, sizeof packed);
    CHECK(n > 0);
    cg_mesh *m = NULL;
    cg_error err;
    CHECK_MSG(cg_mesh_load_memory(packed, n, "t.obj.gz", CG_MESH_FORMAT_AUTO, &m, &err) == CG_OK,
              "%s", err.message);
    if (m)
        CHECK(m->vertex_count == 3 && m->face_count == 1);
    cg_mesh_free(m);
    /* two gzip members one after the other read as their concatenation */
    memcpy(twice, packed, n);
    memcpy(twice + n, packed, n);
    CHECK_MSG(cg_mesh_load_memory(twice, 2 * n, "t.obj.gz", CG_MESH_FORMAT_OBJ, &m, &err) == CG_OK,
              "%s", err.message);
    if (m)
        CHECK(m->vertex_count == 6 && m->face_count == 2);
    cg_mesh_free(m);
    /* gzip inside gzip is refused; garbage after the data is an error */
    size_t nn = gzip_bytes(packed, n, nested, sizeof nested);
    CHECK(cg_mesh_load_memory(nested, nn, "t.obj.gz", CG_MESH_FORMAT_AUTO, &m, &err) == CG_EFORMAT);
    CHECK_MSG(strstr(err.message, "gzip data inside gzip data") != NULL, "%s", err.message);
    memcpy(twice + n, "junk", 4);
    CHECK(cg_mesh_load_memory(twice, n + 4, "t.obj.gz", CG_MESH_FORMAT_AUTO, &m, &err)
          == CG_EFORMAT);
    CHECK_MSG(strstr(err.message, "4 more bytes follow") != NULL, "%s", err.message);
}

/* Every prefix of each small text fixture loads or fails cleanly. */
static void test_prefixes(void)
{
    const char *texts[] = {
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n",
        "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2 1 0 0\n",
        ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
        ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
         "endloop\nendfacet\nendsolid t\n"),
    };
    const char *names[] = {"p.obj", "p.off", "p.ply", "p.stl"};
    for (int i = 0; i < 4; i++) {
        size_t n = strlen(texts[i]);
        for (size_t cut = 0; cut <= n; cut++) {
            cg_mesh *m = NULL;
            cg_error err;
            cg_status s = cg_mesh_load_memory(texts[i], cut, names[i], CG_MESH_FORMAT_AUTO, &m,
                                              &err);
            CHECK((s == CG_OK) == (m != NULL));
            if (s != CG_OK)
                CHECK_MSG(strstr(err.message, names[i]) == err.message, "%s", err.message);
            if (m)
                CHECK(cg_mesh_validate(m, &err) == CG_OK);
            cg_mesh_free(m);
        }
    }
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(make_temp_dir);
    CHECK_GROUP(test_obj);
    CHECK_GROUP(test_obj_materials);
    CHECK_GROUP(test_off);
    CHECK_GROUP(test_ply);
    CHECK_GROUP(test_stl);
    CHECK_GROUP(test_malformed);
    CHECK_GROUP(test_numbers);
    CHECK_GROUP(test_round_trips);
    CHECK_GROUP(test_real_meshes);
    CHECK_GROUP(test_gzip);
    CHECK_GROUP(test_prefixes);
    CHECK_GROUP(remove_temp_dir);
    return check_finish();
}
