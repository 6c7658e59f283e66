/* The glTF 2.0 reader against the specification, on hand-made files: the
 * accessor rules (every component type, normalized integers, byteStride,
 * sparse substitution), the primitive modes, node transforms, materials,
 * the .glb container, and a clear message for every rule a file breaks.
 * Expected values are computed here from the specification's definitions,
 * not by the reader's code. */
#include "cg.h"
#include "check.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- building files ------------------------------------------------------ */

typedef struct bytes {
    unsigned char *data;
    size_t size, capacity;
} bytes;

static void put(bytes *b, const void *data, size_t n)
{
    if (b->size + n > b->capacity) {
        b->capacity = (b->size + n) * 2 + 64;
        b->data = realloc(b->data, b->capacity);
    }
    memcpy(b->data + b->size, data, n);
    b->size += n;
}

static void put_u8(bytes *b, unsigned v)
{
    unsigned char c = (unsigned char)v;
    put(b, &c, 1);
}
static void put_u16(bytes *b, unsigned v)
{
    put_u8(b, v & 255);
    put_u8(b, v >> 8 & 255);
}
static void put_u32(bytes *b, uint32_t v)
{
    put_u16(b, v & 65535);
    put_u16(b, v >> 16);
}
static void put_f32(bytes *b, float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    put_u32(b, v);
}
static void pad_to(bytes *b, size_t multiple, unsigned char with)
{
    while (b->size % multiple)
        put_u8(b, with);
}

static char *base64(const bytes *b)
{
    static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char *out = malloc(b->size / 3 * 4 + 8);
    size_t n = 0;
    for (size_t i = 0; i < b->size; i += 3) {
        uint32_t v = (uint32_t)b->data[i] << 16;
        if (i + 1 < b->size)
            v |= (uint32_t)b->data[i + 1] << 8;
        if (i + 2 < b->size)
            v |= b->data[i + 2];
        out[n++] = table[v >> 18 & 63];
        out[n++] = table[v >> 12 & 63];
        out[n++] = i + 1 < b->size ? table[v >> 6 & 63] : '=';
        out[n++] = i + 2 < b->size ? table[v & 63] : '=';
    }
    out[n] = '\0';
    return out;
}

/* printf into a new string */
static char *format(const char *f, ...)
{
    va_list a, b;
    va_start(a, f);
    va_copy(b, a);
    int n = vsnprintf(NULL, 0, f, a);
    va_end(a);
    char *s = malloc((size_t)n + 1);
    vsnprintf(s, (size_t)n + 1, f, b);
    va_end(b);
    return s;
}

/* A .gltf text with one buffer (the given bytes as a data: URI) and the
 * given JSON members (accessors, bufferViews, meshes, nodes, ...). */
static char *gltf_text(const bytes *buffer, const char *members)
{
    char *b64 = base64(buffer);
    char *text = format("{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": %zu, "
                        "\"uri\": \"data:application/octet-stream;base64,%s\"}], %s}",
                        buffer->size, b64, members);
    free(b64);
    return text;
}

static cg_status load_text(const char *text, const char *name, cg_mesh **mesh, cg_error *err)
{
    cg_error_clear(err);
    return cg_mesh_load_memory(text, strlen(text), name, CG_MESH_FORMAT_AUTO, mesh, err);
}

/* ---- accessors ------------------------------------------------------------- */

/* A random value of a component type, written to b; its decoded value (the
 * specification's normalization) returned. */
static double put_component(bytes *b, int type, int normalized, check_rng *rng)
{
    switch (type) {
    case 5120: {
        int v = (int)check_rng_int(rng, -128, 127);
        put_u8(b, (unsigned)(v & 255));
        return normalized ? fmax(v / 127.0, -1.0) : v;
    }
    case 5121: {
        int v = (int)check_rng_int(rng, 0, 255);
        put_u8(b, (unsigned)v);
        return normalized ? v / 255.0 : v;
    }
    case 5122: {
        int v = (int)check_rng_int(rng, -32768, 32767);
        put_u16(b, (unsigned)(v & 65535));
        return normalized ? fmax(v / 32767.0, -1.0) : v;
    }
    case 5123: {
        int v = (int)check_rng_int(rng, 0, 65535);
        put_u16(b, (unsigned)v);
        return normalized ? v / 65535.0 : v;
    }
    default: {
        float f = (float)check_rng_range(rng, -100, 100);
        put_f32(b, f);
        return f;
    }
    }
}

/* Random triangles whose texture coordinates use every allowed encoding and
 * whose positions sit at random strides and offsets: what the reader gives
 * equals the definition. */
static void accessor_encodings(void)
{
    check_rng rng = {0x5eed};
    static const struct {
        int type, normalized;
    } texcoord_types[] = {{5126, 0}, {5121, 1}, {5123, 1}};
    static const int index_types[] = {5121, 5123, 5125};
    for (int round = 0; round < 300; round++) {
        size_t vertices = (size_t)check_rng_int(&rng, 3, 40);
        size_t triangles = (size_t)check_rng_int(&rng, 1, 30);
        size_t stride = 12 + 4 * (size_t)check_rng_int(&rng, 0, 10);
        size_t offset = 4 * (size_t)check_rng_int(&rng, 0, 3);
        int tt = (int)check_rng_int(&rng, 0, 2);
        int it = index_types[check_rng_int(&rng, 0, 2)];
        int texcoord_type = texcoord_types[tt].type,
            texcoord_normalized = texcoord_types[tt].normalized;
        bytes b = {0};
        /* view 0: positions, interleaved with junk up to the stride */
        for (size_t i = 0; i < offset; i++)
            put_u8(&b, 0xAB);
        double *position = malloc(vertices * 3 * sizeof *position);
        for (size_t v = 0; v < vertices; v++) {
            for (int c = 0; c < 3; c++)
                position[3 * v + (size_t)c] = put_component(&b, 5126, 0, &rng);
            for (size_t pad = 12; pad < stride; pad++)
                put_u8(&b, 0xCD);
        }
        size_t view0_length = b.size;
        pad_to(&b, 4, 0);
        size_t view1 = b.size;
        double *texcoord = malloc(vertices * 2 * sizeof *texcoord);
        for (size_t v = 0; v < vertices; v++)
            for (int c = 0; c < 2; c++)
                texcoord[2 * v + (size_t)c] = put_component(&b, texcoord_type, texcoord_normalized,
                                                            &rng);
        size_t view1_length = b.size - view1;
        pad_to(&b, 4, 0);
        size_t view2 = b.size;
        uint32_t *index = malloc(triangles * 3 * sizeof *index);
        for (size_t i = 0; i < triangles * 3; i++) {
            index[i] = (uint32_t)check_rng_int(&rng, 0, (long long)vertices - 1);
            if (it == 5121)
                put_u8(&b, index[i]);
            else if (it == 5123)
                put_u16(&b, index[i]);
            else
                put_u32(&b, index[i]);
        }
        size_t view2_length = b.size - view2;
        char *members = format(
            "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": %zu, \"byteStride\": %zu},"
            " {\"buffer\": 0, \"byteOffset\": %zu, \"byteLength\": %zu},"
            " {\"buffer\": 0, \"byteOffset\": %zu, \"byteLength\": %zu}],"
            "\"accessors\": [{\"bufferView\": 0, \"byteOffset\": %zu, \"componentType\": 5126, "
            "\"count\": %zu, \"type\": \"VEC3\"},"
            " {\"bufferView\": 1, \"componentType\": %d, \"normalized\": %s, \"count\": %zu, "
            "\"type\": \"VEC2\"},"
            " {\"bufferView\": 2, \"componentType\": %d, \"count\": %zu, \"type\": \"SCALAR\"}],"
            "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0, \"TEXCOORD_0\": 1},"
            " \"indices\": 2}]}], \"nodes\": [{\"mesh\": 0}], \"scenes\": [{\"nodes\": [0]}]",
            view0_length, stride, view1, view1_length, view2, view2_length, offset, vertices,
            texcoord_type, texcoord_normalized ? "true" : "false", vertices, it, triangles * 3);
        char *text = gltf_text(&b, members);
        cg_mesh *mesh = NULL;
        cg_error err;
        cg_status s = load_text(text, "random.gltf", &mesh, &err);
        CHECK_MSG(s == CG_OK, "round %d: %s", round, err.message);
        if (s == CG_OK) {
            CHECK_EQ_INT(mesh->vertex_count, vertices);
            CHECK_EQ_INT(mesh->face_count, triangles);
            long bad = 0;
            for (size_t v = 0; v < vertices && v < mesh->vertex_count; v++) {
                bad += mesh->positions[v].x != position[3 * v]
                       || mesh->positions[v].y != position[3 * v + 1]
                       || mesh->positions[v].z != position[3 * v + 2];
                /* cg's v is glTF's flipped */
                bad += mesh->texcoords[v].x != texcoord[2 * v]
                       || fabs(mesh->texcoords[v].y - (1.0 - texcoord[2 * v + 1])) > 1e-15;
            }
            for (size_t i = 0; i < triangles * 3 && mesh->face_count == triangles; i++)
                bad += mesh->face_indices[i] != index[i];
            CHECK_MSG(bad == 0, "round %d: %ld values differ (stride %zu, texcoord type %d)", round,
                      bad, stride, texcoord_type);
        }
        cg_mesh_free(mesh);
        free(text);
        free(members);
        free(position);
        free(texcoord);
        free(index);
        free(b.data);
    }
}

/* Colours in every component type: normalized integers reach exactly 1. */
static void normalized_colors(void)
{
    static const int types[] = {5121, 5123, 5126};
    check_rng rng = {77};
    for (int t = 0; t < 3; t++) {
        bytes b = {0};
        float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        for (int i = 0; i < 9; i++)
            put_f32(&b, corners[i]);
        double expected[12];
        size_t colors_at = b.size;
        for (int i = 0; i < 12; i++)
            expected[i] = put_component(&b, types[t], types[t] != 5126, &rng);
        pad_to(&b, 4, 0);
        char *members = format(
            "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}, {\"buffer\": 0, "
            "\"byteOffset\": %zu, \"byteLength\": %zu}],"
            "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, "
            "\"type\": \"VEC3\"}, {\"bufferView\": 1, \"componentType\": %d, \"normalized\": %s, "
            "\"count\": 3, \"type\": \"VEC4\"}],"
            "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0, \"COLOR_0\": 1}}]}],"
            "\"nodes\": [{\"mesh\": 0}]",
            colors_at, b.size - colors_at, types[t], types[t] != 5126 ? "true" : "false");
        char *text = gltf_text(&b, members);
        cg_mesh *mesh = NULL;
        cg_error err;
        CHECK_MSG(load_text(text, "colors.gltf", &mesh, &err) == CG_OK, "%s", err.message);
        if (mesh) {
            CHECK(mesh->colors != NULL);
            for (int v = 0; v < 3 && mesh->colors; v++) {
                CHECK_NEAR(mesh->colors[v].r, expected[4 * v], 1e-7);
                CHECK_NEAR(mesh->colors[v].g, expected[4 * v + 1], 1e-7);
                CHECK_NEAR(mesh->colors[v].b, expected[4 * v + 2], 1e-7);
                CHECK_NEAR(mesh->colors[v].a, expected[4 * v + 3], 1e-7);
            }
        }
        cg_mesh_free(mesh);
        free(text);
        free(members);
        free(b.data);
    }
}

/* Sparse accessors: the base (a view's elements or zeros) with the listed
 * elements replaced. */
static void sparse_accessors(void)
{
    check_rng rng = {991};
    for (int round = 0; round < 100; round++) {
        size_t count = (size_t)check_rng_int(&rng, 3, 30);
        int with_base = (int)check_rng_int(&rng, 0, 1);
        bytes b = {0};
        double expected[90];
        for (size_t i = 0; i < count * 3; i++)
            expected[i] = with_base ? put_component(&b, 5126, 0, &rng) : 0;
        size_t base_length = b.size;
        /* sparse indices: a random increasing subset */
        size_t indices_at = b.size, chosen[30], chosen_count = 0;
        for (size_t i = 0; i < count; i++)
            if (check_rng_int(&rng, 0, 2) == 0)
                chosen[chosen_count++] = i;
        if (chosen_count == 0)
            chosen[chosen_count++] = count - 1;
        for (size_t k = 0; k < chosen_count; k++)
            put_u16(&b, (unsigned)chosen[k]);
        pad_to(&b, 4, 0);
        size_t values_at = b.size;
        for (size_t k = 0; k < chosen_count; k++)
            for (int c = 0; c < 3; c++)
                expected[3 * chosen[k] + (size_t)c] = put_component(&b, 5126, 0, &rng);
        char *base_view = format("{\"buffer\": 0, \"byteLength\": %zu}, ", base_length);
        char *members = format(
            "\"bufferViews\": [%s{\"buffer\": 0, \"byteOffset\": %zu, \"byteLength\": %zu}, "
            "{\"buffer\": 0, \"byteOffset\": %zu, \"byteLength\": %zu}],"
            "\"accessors\": [{%s\"componentType\": 5126, \"count\": %zu, \"type\": \"VEC3\", "
            "\"sparse\": {\"count\": %zu, \"indices\": {\"bufferView\": %d, \"componentType\": "
            "5123}, \"values\": {\"bufferView\": %d}}}],"
            "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": 0}]}],"
            "\"nodes\": [{\"mesh\": 0}]",
            with_base ? base_view : "", indices_at, 2 * chosen_count, values_at, 12 * chosen_count,
            with_base ? "\"bufferView\": 0, " : "", count, chosen_count, with_base ? 1 : 0,
            with_base ? 2 : 1);
        /* mode 0 (points) is not drawn: make it triangles when count allows */
        char *triangles = strstr(members, "\"mode\": 0");
        if (count % 3 == 0)
            triangles[8] = '4';
        char *text = gltf_text(&b, members);
        cg_mesh *mesh = NULL;
        cg_error err;
        cg_status s = load_text(text, "sparse.gltf", &mesh, &err);
        CHECK_MSG(s == CG_OK, "round %d: %s", round, err.message);
        if (s == CG_OK && count % 3 == 0) {
            long bad = 0;
            for (size_t v = 0; v < count; v++)
                bad += mesh->positions[v].x != expected[3 * v]
                       || mesh->positions[v].y != expected[3 * v + 1]
                       || mesh->positions[v].z != expected[3 * v + 2];
            CHECK_MSG(bad == 0, "round %d: %ld sparse elements differ", round, bad);
        } else if (s == CG_OK) {
            CHECK_EQ_INT(mesh->face_count, 0);
            CHECK(mesh->notes && strstr(mesh->notes, "point primitive"));
        }
        cg_mesh_free(mesh);
        free(text);
        free(members);
        free(base_view);
        free(b.data);
    }
}

/* ---- primitive modes ------------------------------------------------------ */

/* Strips and fans of n vertices give n - 2 triangles with the
 * specification's corners; lines and points are left out with a note. */
static void primitive_modes(void)
{
    for (int mode = 0; mode <= 6; mode++) {
        for (size_t n = 3; n <= 12; n++) {
            bytes b = {0};
            for (size_t v = 0; v < n; v++) {
                double angle = 6.283185307179586 * (double)v / (double)n;
                put_f32(&b, (float)cos(angle));
                put_f32(&b, (float)sin(angle));
                put_f32(&b, 0);
            }
            char *members = format(
                "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": %zu}],"
                "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": %zu, "
                "\"type\": \"VEC3\"}],"
                "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": "
                "%d}]}], \"nodes\": [{\"mesh\": 0}]",
                b.size, n, mode);
            char *text = gltf_text(&b, members);
            cg_mesh *mesh = NULL;
            cg_error err;
            cg_status s = load_text(text, "modes.gltf", &mesh, &err);
            if (mode == 4 && n % 3) {
                CHECK_MSG(s == CG_EFORMAT && strstr(err.message, "multiple of 3"), "%s",
                          err.message);
            } else {
                CHECK_MSG(s == CG_OK, "mode %d, n %zu: %s", mode, n, err.message);
            }
            if (s == CG_OK) {
                size_t expected = mode == 4 ? n / 3 : mode >= 5 ? n - 2 : 0;
                CHECK_EQ_INT(mesh->face_count, expected);
                long bad = 0;
                for (size_t t = 0; t < mesh->face_count; t++) {
                    const uint32_t *c = mesh->face_indices + 3 * t;
                    size_t want[3];
                    if (mode == 4)
                        want[0] = 3 * t, want[1] = 3 * t + 1, want[2] = 3 * t + 2;
                    else if (mode == 5 && t % 2 == 0)
                        want[0] = t, want[1] = t + 1, want[2] = t + 2;
                    else if (mode == 5)
                        want[0] = t, want[1] = t + 2, want[2] = t + 1;
                    else
                        want[0] = t + 1, want[1] = t + 2, want[2] = 0;
                    bad += c[0] != want[0] || c[1] != want[1] || c[2] != want[2];
                }
                CHECK_MSG(bad == 0, "mode %d, n %zu: %ld triangles differ", mode, n, bad);
                if (mode < 4)
                    CHECK_MSG(mesh->notes && strstr(mesh->notes, mode == 0 ? "point" : "line"),
                              "mode %d: notes '%s'", mode, mesh->notes ? mesh->notes : "");
            }
            cg_mesh_free(mesh);
            free(text);
            free(members);
            free(b.data);
        }
    }
}

/* ---- node transforms ------------------------------------------------------ */

/* q v q* for a unit quaternion (x, y, z, w). */
static cg_vec3 rotate(const double q[4], cg_vec3 v)
{
    /* t = 2 (q.xyz x v); v' = v + w t + q.xyz x t */
    double tx = 2 * (q[1] * v.z - q[2] * v.y), ty = 2 * (q[2] * v.x - q[0] * v.z),
           tz = 2 * (q[0] * v.y - q[1] * v.x);
    return cg_vec3_make(v.x + q[3] * tx + (q[1] * tz - q[2] * ty),
                        v.y + q[3] * ty + (q[2] * tx - q[0] * tz),
                        v.z + q[3] * tz + (q[0] * ty - q[1] * tx));
}

/* A parent with TRS and a child with a matrix: the child's mesh lands at
 * parent(child(p)); a mirroring scale reverses the triangles. */
static void node_transforms(void)
{
    check_rng rng = {4242};
    for (int round = 0; round < 200; round++) {
        double t[3], q[4], sc[3], m[16];
        double length = 0;
        for (int i = 0; i < 4; i++) {
            q[i] = check_rng_range(&rng, -1, 1);
            length += q[i] * q[i];
        }
        for (int i = 0; i < 4; i++)
            q[i] /= sqrt(length);
        for (int i = 0; i < 3; i++) {
            t[i] = check_rng_range(&rng, -10, 10);
            sc[i] = check_rng_range(&rng, 0.2, 3) * (check_rng_int(&rng, 0, 3) == 0 ? -1 : 1);
        }
        /* child: a column-major matrix of random affine entries */
        for (int i = 0; i < 16; i++)
            m[i] = i % 4 == 3 ? (i == 15) : check_rng_range(&rng, -2, 2);
        bytes b = {0};
        float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        for (int i = 0; i < 9; i++)
            put_f32(&b, corners[i]);
        char *members = format(
            "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}],"
            "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": "
            "\"VEC3\"}], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}],"
            "\"nodes\": [{\"children\": [1], \"translation\": [%.17g, %.17g, %.17g], "
            "\"rotation\": [%.17g, %.17g, %.17g, %.17g], \"scale\": [%.17g, %.17g, %.17g]},"
            " {\"mesh\": 0, \"matrix\": [%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, "
            "%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g]}],"
            "\"scenes\": [{\"nodes\": [0]}], \"scene\": 0",
            t[0], t[1], t[2], q[0], q[1], q[2], q[3], sc[0], sc[1], sc[2], m[0], m[1], m[2], m[3],
            m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12], m[13], m[14], m[15]);
        char *text = gltf_text(&b, members);
        cg_mesh *mesh = NULL;
        cg_error err;
        CHECK_MSG(load_text(text, "nodes.gltf", &mesh, &err) == CG_OK, "%s", err.message);
        if (mesh) {
            double determinant = sc[0] * sc[1] * sc[2]
                                 * (m[0] * (m[5] * m[10] - m[9] * m[6])
                                    - m[4] * (m[1] * m[10] - m[9] * m[2])
                                    + m[8] * (m[1] * m[6] - m[5] * m[2]));
            for (int v = 0; v < 3; v++) {
                double x = corners[3 * v], y = corners[3 * v + 1], z = corners[3 * v + 2];
                cg_vec3 child = cg_vec3_make(m[0] * x + m[4] * y + m[8] * z + m[12],
                                             m[1] * x + m[5] * y + m[9] * z + m[13],
                                             m[2] * x + m[6] * y + m[10] * z + m[14]);
                cg_vec3 scaled = cg_vec3_make(child.x * sc[0], child.y * sc[1], child.z * sc[2]);
                cg_vec3 r = rotate(q, scaled);
                cg_vec3 world = cg_vec3_make(r.x + t[0], r.y + t[1], r.z + t[2]);
                CHECK_NEAR(mesh->positions[v].x, world.x, 1e-9);
                CHECK_NEAR(mesh->positions[v].y, world.y, 1e-9);
                CHECK_NEAR(mesh->positions[v].z, world.z, 1e-9);
            }
            const uint32_t *c = mesh->face_indices;
            if (determinant < 0)
                CHECK_MSG(c[0] == 0 && c[1] == 2 && c[2] == 1, "round %d: mirrored, not reversed",
                          round);
            else
                CHECK_MSG(c[0] == 0 && c[1] == 1 && c[2] == 2, "round %d: reversed", round);
        }
        cg_mesh_free(mesh);
        free(text);
        free(members);
        free(b.data);
    }
}

/* ---- broken files ----------------------------------------------------------- */

/* One triangle, 36 bytes of positions then 3 bytes of indices, with
 * whatever members the case gives in place of the defaults. */
static char *triangle_text(const char *views, const char *accessors, const char *meshes,
                           const char *nodes)
{
    bytes b = {0};
    float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (int i = 0; i < 9; i++)
        put_f32(&b, corners[i]);
    put_u8(&b, 0);
    put_u8(&b, 1);
    put_u8(&b, 2);
    char *members = format(
        "\"bufferViews\": %s, \"accessors\": %s, \"meshes\": %s, \"nodes\": %s",
        views ? views
              : "[{\"buffer\": 0, \"byteLength\": 36}, {\"buffer\": 0, \"byteOffset\": 36, "
                "\"byteLength\": 3}]",
        accessors ? accessors
                  : "[{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": "
                    "\"VEC3\"}, {\"bufferView\": 1, \"componentType\": 5121, \"count\": 3, "
                    "\"type\": \"SCALAR\"}]",
        meshes ? meshes
               : "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}]}]",
        nodes ? nodes : "[{\"mesh\": 0}]");
    char *text = gltf_text(&b, members);
    free(members);
    free(b.data);
    return text;
}

static void broken_files(void)
{
    static const struct {
        const char *views, *accessors, *meshes, *nodes;
        const char *says;
    } cases[] = {
        {NULL, NULL, NULL, NULL, NULL}, /* the valid file itself */
        {NULL,
         "[{\"bufferView\": 0, \"componentType\": 5126, \"count\": 4, \"type\": \"VEC3\"}, "
         "{\"bufferView\": 1, \"componentType\": 5121, \"count\": 3, \"type\": \"SCALAR\"}]",
         NULL, NULL,
         "accessors[0]: expected 4 elements of 12 bytes (stride 12) from byteOffset 0 "
         "to fit in bufferViews[0] (36 bytes)"},
        {NULL,
         "[{\"bufferView\": 0, \"byteOffset\": 4, \"componentType\": 5126, \"count\": 3, "
         "\"type\": \"VEC3\"}, {\"bufferView\": 1, \"componentType\": 5121, \"count\": 3, "
         "\"type\": \"SCALAR\"}]",
         NULL, NULL, "but they end at byte 40"},
        {"[{\"buffer\": 0, \"byteLength\": 36}, {\"buffer\": 0, \"byteOffset\": 36, "
         "\"byteLength\": 4}]",
         NULL, NULL, NULL, "bufferViews[1]: expected to lie inside buffers[0] (39 bytes)"},
        {"[{\"buffer\": 1, \"byteLength\": 36}]", NULL, NULL, NULL,
         "bufferViews[0].buffer: expected an index into buffers (0 to 0), got the number 1"},
        {NULL, NULL, "[{\"primitives\": [{\"attributes\": {\"POSITION\": 1}}]}]", NULL,
         "attributes.POSITION: expected an accessor of VEC3 floats"},
        {NULL, NULL, "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"indices\": 0}]}]",
         NULL, "indices: expected an accessor of unsigned byte, short or int SCALARs"},
        {NULL, NULL, "[{\"primitives\": [{\"attributes\": {\"POSITION\": 2}}]}]", NULL,
         "POSITION: expected an index into accessors (0 to 1), got the number 2"},
        {NULL, NULL, "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": 7}]}]", NULL,
         "mode: expected an integer in [0, 6], got the number 7"},
        {NULL, NULL, "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0, \"UV\": 0}}]}]", NULL,
         "attributes.UV: expected POSITION, NORMAL"},
        {NULL, NULL, NULL, "[{\"mesh\": 0, \"children\": [1]}, {\"children\": [0]}]", "node cycle"},
        {NULL, NULL, NULL, "[{\"mesh\": 0, \"children\": [0]}]", "is its own child"},
        {NULL, NULL, NULL, "[{\"children\": [2]}, {\"children\": [2]}, {\"mesh\": 0}]",
         "nodes[1].children[0]: expected a node without a parent, but node 2 is already a "
         "child of node 0"},
        {NULL, NULL, NULL,
         "[{\"mesh\": 0, \"matrix\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, "
         "0, 0, 1], \"scale\": [1, 1, 1]}]",
         "expected either matrix or translation/rotation/scale, got both"},
        {NULL, NULL, NULL, "[{\"mesh\": 0, \"rotation\": [0, 0, 0]}]",
         "nodes[0].rotation: expected an array of 4 numbers"},
        {NULL, NULL, NULL, "[{\"mesh\": 3}]", "nodes[0].mesh: expected an index into meshes"},
        {NULL, "[{\"bufferView\": 0, \"componentType\": 5127, \"count\": 3, \"type\": \"VEC3\"}]",
         NULL, NULL, "accessors[0].componentType: expected 5120, 5121, 5122, 5123, 5125 or 5126"},
        {NULL, "[{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC5\"}]",
         NULL, NULL, "accessors[0].type: expected \"SCALAR\""},
        {NULL,
         "[{\"bufferView\": 0, \"componentType\": 5126, \"normalized\": true, \"count\": 3, "
         "\"type\": \"VEC3\"}]",
         NULL, NULL, "normalized: expected false for float"},
        {NULL, "[{\"bufferView\": 0, \"componentType\": 5126, \"count\": 0, \"type\": \"VEC3\"}]",
         NULL, NULL, "accessors[0].count: expected an integer in [1, "},
        {NULL,
         "[{\"bufferView\": 0, \"byteOffset\": 2, \"componentType\": 5126, \"count\": 2, "
         "\"type\": \"VEC3\"}]",
         NULL, NULL, "expected the data to start at a multiple of 4 bytes"},
        {"[{\"buffer\": 0, \"byteLength\": 36, \"byteStride\": 8}]", NULL, NULL, NULL,
         "bufferViews[0].byteStride: expected at least 12"},
        {"[{\"buffer\": 0, \"byteLength\": 36, \"byteStride\": 14}]", NULL, NULL, NULL,
         "byteStride: expected a multiple of 4"},
        {"[{\"buffer\": 0, \"byteLength\": 36, \"byteStride\": 256}]", NULL, NULL, NULL,
         "byteStride: expected an integer in [4, 252]"},
        {NULL,
         "[{\"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", \"sparse\": {\"count\": "
         "2, \"indices\": {\"bufferView\": 1, \"componentType\": 5125}, \"values\": "
         "{\"bufferView\": 0}}}]",
         NULL, NULL, "sparse.indices: expected 8 index bytes inside bufferViews[1] (3 bytes)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *text = triangle_text(cases[i].views, cases[i].accessors, cases[i].meshes,
                                   cases[i].nodes);
        cg_mesh *mesh = NULL;
        cg_error err;
        cg_status s = load_text(text, "broken.gltf", &mesh, &err);
        if (!cases[i].says) {
            CHECK_MSG(s == CG_OK && mesh && mesh->face_count == 1, "valid case: %s", err.message);
        } else {
            CHECK_MSG(s != CG_OK && !mesh, "case %zu loaded", i);
            CHECK_MSG(strncmp(err.message, "broken.gltf: ", 13) == 0
                          && strstr(err.message, cases[i].says),
                      "case %zu: '%s' should say '%s'", i, err.message, cases[i].says);
        }
        cg_mesh_free(mesh);
        free(text);
    }
    /* sparse indices must increase */
    bytes b = {0};
    for (int i = 0; i < 9; i++)
        put_f32(&b, 0.5f);
    put_u8(&b, 2);
    put_u8(&b, 1);
    char *members = strdup(
        "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 24}, {\"buffer\": 0, \"byteOffset\": "
        "36, \"byteLength\": 2}], \"accessors\": [{\"componentType\": 5126, \"count\": 3, "
        "\"type\": \"VEC3\", \"sparse\": {\"count\": 2, \"indices\": {\"bufferView\": 1, "
        "\"componentType\": 5121}, \"values\": {\"bufferView\": 0}}}], \"meshes\": "
        "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}], \"nodes\": [{\"mesh\": 0}]");
    char *text = gltf_text(&b, members);
    cg_mesh *mesh = NULL;
    cg_error err;
    CHECK(load_text(text, "sparse.gltf", &mesh, &err) == CG_EFORMAT
          && strstr(err.message, "expected strictly increasing indices below 3, got 1 after 2"));
    free(text);
    free(members);
    free(b.data);
    /* whole-document rules */
    static const struct {
        const char *text, *says;
    } documents[] = {
        {"{\"asset\": {\"version\": \"2.0\"}", "JSON line 1 (byte "},
        {"{\"asset\": {\"version\": \"1.0\"}}", "asset.version: expected \"2.x\""},
        {"{\"asset\": {}}", "asset.version: expected a string"},
        {"[1, 2]", "expected a JSON object"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"extensionsRequired\": "
         "[\"EXT_meshopt_compression\"]}",
         "requires the extension EXT_meshopt_compression, which cg does not read"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 4, \"uri\": "
         "\"data:application/octet-stream;base64,AA!A\"}]}",
         "buffers[0].uri: expected base64 text"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 4, \"uri\": "
         "\"data:application/octet-stream;base64,AAA=\"}]}",
         "buffers[0].byteLength: expected at most the 2 bytes the data holds, got 4"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 4, \"uri\": "
         "\"side.bin\"}]}",
         "the file \"side.bin\" is not read when the glTF comes from memory"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 4, \"uri\": "
         "\"http://example.com/a.bin\"}]}",
         "expected a relative file name or a data: URI"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 4}]}",
         "buffers[0]: expected a uri"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [{\"nodes\": [0]}]}",
         "scenes[0].nodes[0]: expected an index into nodes, but the file has none"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{}, {\"children\": [0]}], \"scenes\": "
         "[{\"nodes\": [0]}]}",
         "scenes[0].nodes[0]: expected a root node, but node 0 is a child of node 1"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"pbrMetallicRoughness\": "
         "{\"metallicFactor\": 2}}]}",
         "materials[0].pbrMetallicRoughness.metallicFactor: expected a number in [0, 1], got "
         "the number 2"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"alphaMode\": \"CLEAR\"}]}",
         "materials[0].alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\""},
        {"{\"asset\": {\"version\": \"2.0\"}, \"cameras\": [{\"type\": \"perspective\", "
         "\"perspective\": {\"yfov\": 0.8, \"znear\": 0}}]}",
         "cameras[0].perspective: expected znear > 0"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"cameras\": [{\"type\": \"orthographic\", "
         "\"orthographic\": {\"xmag\": 1, \"ymag\": 1, \"znear\": 2, \"zfar\": 1}}]}",
         "cameras[0].orthographic: expected znear >= 0 and zfar > znear"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"cameras\": [{\"type\": \"fisheye\"}]}",
         "cameras[0].type: expected \"perspective\" or \"orthographic\""},
        {"{\"asset\": {\"version\": \"2.0\"}, \"extensions\": {\"KHR_lights_punctual\": "
         "{\"lights\": [{\"type\": \"spot\", \"spot\": {\"innerConeAngle\": 1, "
         "\"outerConeAngle\": 0.5}}]}}}",
         "lights[0].spot: expected 0 <= innerConeAngle < outerConeAngle <= pi/2"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"extensions\": {\"KHR_lights_punctual\": "
         "{\"lights\": [{\"type\": \"point\", \"intensity\": -1}]}}}",
         "lights[0]: expected intensity >= 0"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"extensions\": {\"KHR_lights_punctual\": "
         "{\"lights\": [{\"type\": \"point\"}]}}, \"nodes\": [{\"extensions\": "
         "{\"KHR_lights_punctual\": {\"light\": 1}}}]}",
         "nodes[0].extensions.KHR_lights_punctual.light: expected an index into "
         "KHR_lights_punctual.lights (0 to 0), got the number 1"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"samplers\": [{\"wrapS\": 1}]}",
         "samplers[0].wrapS: expected 33071 (CLAMP_TO_EDGE)"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"images\": [{}], \"textures\": [{\"source\": 0}],"
         " \"materials\": [{\"emissiveTexture\": {\"index\": 0}}]}",
         "images[0]: expected either a uri or a bufferView, got neither"},
    };
    /* memory follows the file: a huge all-zero accessor, or a mesh repeated
     * by many nodes, is refused before anything that size is allocated */
    bytes nodes = {0};
    const char *head = "{\"asset\": {\"version\": \"2.0\"}, \"accessors\": [{\"componentType\": "
                       "5126, \"count\": 300000, \"type\": \"VEC3\"}], \"meshes\": "
                       "[{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"mode\": 0}]}], "
                       "\"nodes\": [";
    put(&nodes, head, strlen(head));
    for (int i = 0; i < 200; i++)
        put(&nodes, i ? ", {\"mesh\": 0}" : "{\"mesh\": 0}", i ? 13 : 11);
    put(&nodes, "]}", 3);
    mesh = NULL;
    CHECK_MSG(load_text((const char *)nodes.data, "points.gltf", &mesh, &err) == CG_OK,
              "points are never made: %s", err.message);
    cg_mesh_free(mesh);
    char *triangles = strstr((char *)nodes.data, "\"mode\": 0");
    triangles[8] = '4';
    mesh = NULL;
    CHECK_MSG(load_text((const char *)nodes.data, "forest.gltf", &mesh, &err) == CG_ERANGE && !mesh
                  && strstr(err.message, "forest.gltf: meshes[0]: the default scene's instances "
                                         "make more than"),
              "%s", err.message);
    free(nodes.data);
    const char *zeros = "{\"asset\": {\"version\": \"2.0\"}, \"accessors\": "
                        "[{\"componentType\": 5126, \"count\": 4000000000, \"type\": \"MAT4\"}]}";
    CHECK_MSG(load_text(zeros, "zeros.gltf", &mesh, &err) == CG_ERANGE
                  && strstr(err.message, "zeros.gltf: accessors[0].count: 4000000000 MAT4 "
                                         "elements without a bufferView"),
              "%s", err.message);
    const char *lit = "{\"asset\": {\"version\": \"2.0\"}, \"cameras\": [{\"type\": "
                      "\"perspective\", \"perspective\": {\"yfov\": 0.8, \"znear\": 0.1}}], "
                      "\"extensions\": {\"KHR_lights_punctual\": {\"lights\": [{\"type\": "
                      "\"spot\", \"color\": [1, 0.5, 0], \"spot\": {}}]}}, \"nodes\": "
                      "[{\"camera\": 0, \"extensions\": {\"KHR_lights_punctual\": {\"light\": "
                      "0}}}]}";
    mesh = NULL;
    CHECK_MSG(load_text(lit, "lit.gltf", &mesh, &err) == CG_OK, "%s", err.message);
    CHECK(mesh && mesh->notes && strstr(mesh->notes, "lit.gltf: 1 camera(s)")
          && strstr(mesh->notes, "1 KHR_lights_punctual light(s)"));
    cg_mesh_free(mesh);
    for (size_t i = 0; i < sizeof documents / sizeof documents[0]; i++) {
        mesh = NULL;
        cg_status s = load_text(documents[i].text, "doc.gltf", &mesh, &err);
        CHECK_MSG(s != CG_OK && !mesh && strncmp(err.message, "doc.gltf: ", 10) == 0
                      && strstr(err.message, documents[i].says),
                  "document %zu: '%s' should say '%s'", i, err.message, documents[i].says);
        cg_mesh_free(mesh);
    }
}

/* ---- .glb ------------------------------------------------------------------ */

static bytes glb_of(const char *json, const bytes *binary)
{
    bytes j = {0}, out = {0};
    put(&j, json, strlen(json));
    pad_to(&j, 4, ' ');
    size_t binary_chunk = binary ? 8 + (binary->size + 3) / 4 * 4 : 0;
    put(&out, "glTF", 4);
    put_u32(&out, 2);
    put_u32(&out, (uint32_t)(12 + 8 + j.size + binary_chunk));
    put_u32(&out, (uint32_t)j.size);
    put_u32(&out, 0x4E4F534Au);
    put(&out, j.data, j.size);
    if (binary) {
        put_u32(&out, (uint32_t)((binary->size + 3) / 4 * 4));
        put_u32(&out, 0x004E4942u);
        put(&out, binary->data, binary->size);
        pad_to(&out, 4, 0);
    }
    free(j.data);
    return out;
}

/* The same triangle from a .gltf with a data: URI and from a .glb's BIN
 * chunk; every shorter prefix of the .glb is refused with a message. */
static void glb_container(void)
{
    bytes b = {0};
    float corners[9] = {0, 0, 0, 2, 0, 0, 0, 3, 1};
    for (int i = 0; i < 9; i++)
        put_f32(&b, corners[i]);
    const char *json = "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 36}], "
                       "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}], \"accessors\": "
                       "[{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": "
                       "\"VEC3\"}], \"meshes\": [{\"primitives\": [{\"attributes\": "
                       "{\"POSITION\": 0}}]}], \"nodes\": [{\"mesh\": 0, \"translation\": [1, 2, "
                       "3]}]}";
    bytes glb = glb_of(json, &b);
    cg_mesh *mesh = NULL;
    cg_error err;
    CHECK_MSG(cg_mesh_load_memory(glb.data, glb.size, "tri.glb", CG_MESH_FORMAT_AUTO, &mesh, &err)
                  == CG_OK,
              "%s", err.message);
    if (mesh) {
        CHECK_EQ_INT(mesh->face_count, 1);
        for (int v = 0; v < 3; v++) {
            CHECK(mesh->positions[v].x == corners[3 * v] + 1);
            CHECK(mesh->positions[v].y == corners[3 * v + 1] + 2);
            CHECK(mesh->positions[v].z == corners[3 * v + 2] + 3);
        }
    }
    cg_mesh_free(mesh);
    /* any name: the magic tells */
    CHECK(cg_mesh_load_memory(glb.data, glb.size, "tri.obj", CG_MESH_FORMAT_AUTO, &mesh, &err)
          == CG_OK);
    cg_mesh_free(mesh);
    long bad = 0;
    for (size_t n = 0; n < glb.size; n++) {
        mesh = NULL;
        cg_error_clear(&err);
        cg_status s = cg_mesh_load_memory(glb.data, n, "cut.glb", CG_MESH_FORMAT_GLTF, &mesh, &err);
        bad += s == CG_OK || mesh || (n && strncmp(err.message, "cut.glb: ", 9) != 0);
        cg_mesh_free(mesh);
    }
    CHECK_MSG(bad == 0, "%ld truncated .glb files were not refused with a message", bad);
    /* header rules */
    glb.data[4] = 1;
    CHECK(cg_mesh_load_memory(glb.data, glb.size, "v1.glb", CG_MESH_FORMAT_AUTO, &mesh, &err)
              == CG_EUNSUPPORTED
          && strstr(err.message, "expected GLB version 2, got 1"));
    glb.data[4] = 2;
    glb.data[8] ^= 4;
    CHECK(cg_mesh_load_memory(glb.data, glb.size, "len.glb", CG_MESH_FORMAT_AUTO, &mesh, &err)
              == CG_EFORMAT
          && strstr(err.message, "expected the GLB length to be the file size"));
    glb.data[8] ^= 4;
    glb.data[16] = 'X';
    CHECK(cg_mesh_load_memory(glb.data, glb.size, "chunk.glb", CG_MESH_FORMAT_AUTO, &mesh, &err)
              == CG_EFORMAT
          && strstr(err.message, "expected the JSON chunk first"));
    free(glb.data);
    /* a .glb without BIN chunk cannot leave buffers[0].uri out */
    glb = glb_of(json, NULL);
    CHECK(cg_mesh_load_memory(glb.data, glb.size, "nobin.glb", CG_MESH_FORMAT_AUTO, &mesh, &err)
              == CG_EFORMAT
          && strstr(err.message, "buffers[0]: expected a uri"));
    free(glb.data);
    free(b.data);
}

/* An external .bin and image beside the .gltf, with a space in their
 * names (percent-escaped in the URI); a missing .bin names the file. */
static void external_files(void)
{
    char dir[] = "/tmp/cg_gltf_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[256];
    snprintf(path, sizeof path, "%s/my data.bin", dir);
    FILE *f = fopen(path, "wb");
    float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    fwrite(corners, 4, 9, f);
    fclose(f);
    const char *json = "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 36, "
                       "\"uri\": \"my%20data.bin\"}], \"bufferViews\": [{\"buffer\": 0, "
                       "\"byteLength\": 36}], \"accessors\": [{\"bufferView\": 0, "
                       "\"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\"}], "
                       "\"images\": [{\"uri\": \"wood%20grain.png\"}], \"samplers\": "
                       "[{\"wrapS\": 33071, \"wrapT\": 33648, \"magFilter\": 9728}], "
                       "\"textures\": [{\"source\": 0, \"sampler\": 0}], \"materials\": "
                       "[{\"name\": \"wood\", \"pbrMetallicRoughness\": {\"baseColorFactor\": "
                       "[0.5, 0.25, 1, 0.75], \"metallicFactor\": 0.125, \"baseColorTexture\": "
                       "{\"index\": 0, \"extensions\": {\"KHR_texture_transform\": {\"offset\": "
                       "[0.5, 0], \"rotation\": 1.5, \"scale\": [2, 3]}}}}, \"emissiveFactor\": "
                       "[1, 0.5, 0], \"extensions\": {\"KHR_materials_emissive_strength\": "
                       "{\"emissiveStrength\": 4}}, \"alphaMode\": \"MASK\", \"alphaCutoff\": "
                       "0.25, \"doubleSided\": true}], \"meshes\": [{\"primitives\": "
                       "[{\"attributes\": {\"POSITION\": 0}, \"material\": 0}]}], \"nodes\": "
                       "[{\"mesh\": 0}]}";
    snprintf(path, sizeof path, "%s/model.gltf", dir);
    f = fopen(path, "wb");
    fputs(json, f);
    fclose(f);
    cg_mesh *mesh = NULL;
    cg_error err;
    CHECK_MSG(cg_mesh_load(path, &mesh, &err) == CG_OK, "%s", err.message);
    if (mesh) {
        CHECK_EQ_INT(mesh->face_count, 1);
        CHECK(mesh->positions[1].x == 1);
        CHECK_EQ_INT(mesh->material_count, 1);
        CHECK(mesh->face_materials && mesh->face_materials[0] == 0);
        const cg_mesh_material *m = mesh->materials;
        CHECK(strcmp(m->name, "wood") == 0);
        CHECK(m->model == CG_MESH_MATERIAL_METALLIC_ROUGHNESS);
        CHECK(m->base_color.r == 0.5f && m->base_color.g == 0.25f && m->base_color.b == 1
              && m->base_color.a == 0.75f);
        CHECK(m->metallic == 0.125 && m->roughness == 1);
        CHECK(m->emissive.r == 4 && m->emissive.g == 2 && m->emissive.b == 0);
        CHECK(m->alpha_mode == CG_MESH_ALPHA_MASK && m->alpha_cutoff == 0.25 && m->double_sided);
        char image[300];
        snprintf(image, sizeof image, "%s/wood grain.png", dir);
        CHECK_MSG(m->base_color_map.image_path && strcmp(m->base_color_map.image_path, image) == 0,
                  "image path '%s'", m->base_color_map.image_path);
        CHECK(m->base_color_map.encoding == CG_TEXTURE_SRGB
              && m->normal_map.encoding == CG_TEXTURE_LINEAR);
        CHECK(m->base_color_map.wrap_u == CG_TEXTURE_CLAMP
              && m->base_color_map.wrap_v == CG_TEXTURE_MIRRORED_REPEAT
              && m->base_color_map.magnify_nearest);
        CHECK(m->base_color_map.offset[0] == 0.5 && m->base_color_map.rotation == 1.5
              && m->base_color_map.scale[0] == 2 && m->base_color_map.scale[1] == 3);
        CHECK(m->normal_map.image_path == NULL && m->normal_map.image_bytes == NULL);
    }
    cg_mesh_free(mesh);
    snprintf(path, sizeof path, "%s/my data.bin", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/model.gltf", dir);
    mesh = NULL;
    CHECK(cg_mesh_load(path, &mesh, &err) == CG_EIO && !mesh
          && strstr(err.message, "buffers[0].uri: ") && strstr(err.message, "my data.bin"));
    remove(path);
    rmdir(dir);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(accessor_encodings);
    CHECK_GROUP(normalized_colors);
    CHECK_GROUP(sparse_accessors);
    CHECK_GROUP(primitive_modes);
    CHECK_GROUP(node_transforms);
    CHECK_GROUP(broken_files);
    CHECK_GROUP(glb_container);
    CHECK_GROUP(external_files);
    return check_finish();
}
