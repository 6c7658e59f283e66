/* Loading mesh files: reading (and gunzipping) the bytes, telling the format
 * from the content or the name, and calling the reader. */
#include "internal.h"
#include "../core/array.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <strings.h>
#include <sys/stat.h>
#include <zlib.h>

static int has_suffix(const char *name, size_t length, const char *suffix)
{
    size_t n = strlen(suffix);
    return length >= n && strncasecmp(name + length - n, suffix, n) == 0;
}

cg_mesh_format cg_mesh_format_from_path(const char *path)
{
    if (!path)
        return CG_MESH_FORMAT_AUTO;
    size_t length = strlen(path);
    if (has_suffix(path, length, ".gz"))
        length -= 3;
    if (has_suffix(path, length, ".obj"))
        return CG_MESH_FORMAT_OBJ;
    if (has_suffix(path, length, ".off"))
        return CG_MESH_FORMAT_OFF;
    if (has_suffix(path, length, ".ply"))
        return CG_MESH_FORMAT_PLY;
    if (has_suffix(path, length, ".stl"))
        return CG_MESH_FORMAT_STL;
    if (has_suffix(path, length, ".gltf") || has_suffix(path, length, ".glb"))
        return CG_MESH_FORMAT_GLTF;
    return CG_MESH_FORMAT_AUTO;
}

/* Appends to a growing buffer (src/core/array.h), keeping one spare byte
 * after the data; fails beyond CG_MESH_MAX_FILE_BYTES. */
static cg_status append(unsigned char **buffer, size_t *size, size_t *capacity,
                        const unsigned char *bytes, size_t n)
{
    if (n > CG_MESH_MAX_FILE_BYTES - *size)
        return CG_ERANGE;
    if (core_array_reserve((void **)buffer, capacity, *size + n + 1, 1) != CG_OK)
        return CG_ENOMEM;
    memcpy(*buffer + *size, bytes, n);
    *size += n;
    return CG_OK;
}

static int is_gzip(const unsigned char *bytes, size_t size)
{
    return size >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b;
}

/* Decompresses every gzip member of bytes into a new buffer. */
static cg_status gunzip(const unsigned char *bytes, size_t size, const char *name,
                        unsigned char **out, size_t *out_size, cg_error *err)
{
    z_stream z;
    memset(&z, 0, sizeof z);
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK)
        return cg_error_set(err, CG_ENOMEM, "%s: cannot start gzip decompression", name);
    unsigned char *buffer = NULL, chunk[65536];
    size_t used = 0, capacity = 0, consumed = 0;
    cg_status s = CG_OK;
    while (s == CG_OK) {
        size_t remaining = size - consumed;
        z.next_in = (unsigned char *)(uintptr_t)(bytes + consumed);
        z.avail_in = remaining > UINT32_MAX ? UINT32_MAX : (uInt)remaining;
        size_t before = z.avail_in;
        z.next_out = chunk;
        z.avail_out = sizeof chunk;
        int rc = inflate(&z, Z_NO_FLUSH);
        consumed += before - z.avail_in;
        size_t produced = sizeof chunk - z.avail_out;
        if (produced && (s = append(&buffer, &used, &capacity, chunk, produced)) != CG_OK) {
            s = cg_error_set(err, s, "%s: decompressed data over %zu bytes", name,
                             (size_t)CG_MESH_MAX_FILE_BYTES);
            break;
        }
        if (rc == Z_STREAM_END) {
            /* another member may follow (concatenated .gz files) */
            if (consumed < size && is_gzip(bytes + consumed, size - consumed)) {
                inflateReset(&z);
                continue;
            }
            if (consumed < size)
                s = cg_error_set(err, CG_EFORMAT,
                                 "%s: byte %zu: expected the end of the gzip data, %zu more "
                                 "bytes follow",
                                 name, consumed, size - consumed);
            break;
        }
        if (rc == Z_BUF_ERROR && consumed == size && produced == 0) {
            s = cg_error_set(err, CG_EFORMAT, "%s: byte %zu: gzip data ends early (truncated)",
                             name, consumed);
            break;
        }
        if (rc != Z_OK && rc != Z_BUF_ERROR) {
            s = cg_error_set(err, rc == Z_MEM_ERROR ? CG_ENOMEM : CG_EFORMAT,
                             "%s: byte %zu: bad gzip data (%s)", name, consumed,
                             z.msg ? z.msg : "corrupt");
            break;
        }
    }
    inflateEnd(&z);
    if (s != CG_OK) {
        free(buffer);
        return s;
    }
    if (!buffer && !(buffer = malloc(1))) /* empty but valid */
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", name);
    *out = buffer;
    *out_size = used;
    return CG_OK;
}

cg_status mesh_read_file(const char *path, unsigned char **bytes, size_t *size, cg_error *err)
{
    *bytes = NULL;
    *size = 0;
    FILE *file = fopen(path, "rb");
    if (!file)
        return cg_error_set(err, CG_EIO, "%s: cannot open: %s", path, strerror(errno));
    unsigned char *buffer = NULL, chunk[65536];
    size_t used = 0, capacity = 0, got;
    cg_status s = CG_OK;
    /* a regular file is read straight into a buffer of its size; anything
     * else (a pipe, a file growing meanwhile) through growing chunks */
    struct stat st;
    if (fstat(fileno(file), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0
        && (uint64_t)st.st_size <= CG_MESH_MAX_FILE_BYTES) {
        capacity = (size_t)st.st_size + 1; /* the spare byte append keeps too */
        if (!(buffer = malloc(capacity)))
            s = CG_ENOMEM;
        while (s == CG_OK && used < capacity - 1
               && (got = fread(buffer + used, 1, capacity - 1 - used, file)) > 0)
            used += got;
    }
    while (s == CG_OK && (got = fread(chunk, 1, sizeof chunk, file)) > 0)
        if ((s = append(&buffer, &used, &capacity, chunk, got)) != CG_OK)
            break;
    int failed = ferror(file);
    fclose(file);
    if (s != CG_OK || failed) {
        free(buffer);
        if (s != CG_OK)
            return cg_error_set(err, s, "%s: file larger than %zu bytes or out of memory", path,
                                (size_t)CG_MESH_MAX_FILE_BYTES);
        return cg_error_set(err, CG_EIO, "%s: read error", path);
    }
    if (!buffer && !(buffer = malloc(1)))
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    *bytes = buffer;
    *size = used;
    return CG_OK;
}

/* True when the text starts with an OFF keyword: [ST][C][N][4][n]OFF. */
static int looks_like_off(const unsigned char *b, size_t size)
{
    size_t i = 0;
    while (i < size && (b[i] == ' ' || b[i] == '\t'))
        i++;
    if (i + 1 < size && b[i] == 'S' && b[i + 1] == 'T')
        i += 2;
    while (i < size && (b[i] == 'C' || b[i] == 'N' || b[i] == '4' || b[i] == 'n'))
        i++;
    return i + 3 <= size && memcmp(b + i, "OFF", 3) == 0
           && (i + 3 == size || b[i + 3] == ' ' || b[i + 3] == '\t' || b[i + 3] == '\n'
               || b[i + 3] == '\r' || b[i + 3] == '#');
}

/* The format a file's first bytes show, or AUTO when they do not tell. */
static cg_mesh_format sniff(const unsigned char *b, size_t size)
{
    if (size >= 4 && memcmp(b, "ply", 3) == 0 && (b[3] == '\n' || b[3] == '\r'))
        return CG_MESH_FORMAT_PLY;
    if (looks_like_off(b, size))
        return CG_MESH_FORMAT_OFF;
    if (size >= 84) {
        uint32_t n = (uint32_t)b[80] | (uint32_t)b[81] << 8 | (uint32_t)b[82] << 16
                     | (uint32_t)b[83] << 24;
        if ((uint64_t)n * 50 + 84 == size)
            return CG_MESH_FORMAT_STL;
    }
    size_t i = 0;
    while (i < size && (b[i] == ' ' || b[i] == '\t'))
        i++;
    if (size >= 4 && memcmp(b, "glTF", 4) == 0)
        return CG_MESH_FORMAT_GLTF;
    if (mesh_looks_like_gltf_json(b, size))
        return CG_MESH_FORMAT_GLTF;
    if (size - i >= 6 && memcmp(b + i, "solid", 5) == 0
        && (b[i + 5] == ' ' || b[i + 5] == '\t' || b[i + 5] == '\n' || b[i + 5] == '\r'))
        return CG_MESH_FORMAT_STL;
    return CG_MESH_FORMAT_AUTO;
}

/* The directory part of path ("" for none), as a new string. */
static char *directory_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t length = slash ? (size_t)(slash - path) : 0;
    if (slash && length == 0)
        length = 1; /* "/file.obj" */
    char *dir = malloc(length + 2);
    if (!dir)
        return NULL;
    if (!slash) {
        memcpy(dir, ".", 2);
    } else {
        memcpy(dir, path, length);
        dir[length] = '\0';
    }
    return dir;
}

static cg_status unsupported(const char *name, const char *format, const char *how, cg_error *err)
{
    return cg_error_set(err, CG_EUNSUPPORTED,
                        "%s: %s %s, which cg does not read (yet); cg reads OBJ, OFF, PLY, STL and "
                        "glTF meshes",
                        name, how, format);
}

/* gzip is looked through once: a .gz inside a .gz (or a gzip quine) is not opened. */
static cg_status load(const unsigned char *bytes, size_t size, const char *name,
                      cg_mesh_format format, const char *directory, int gzip_allowed, cg_mesh **out,
                      cg_error *err)
{
    if (!out)
        return cg_error_set(err, CG_EINVAL, "%s: no output mesh given", name ? name : "mesh");
    *out = NULL;
    if (!name)
        name = "mesh";
    if (!bytes && size)
        return cg_error_set(err, CG_EINVAL, "%s: no bytes given", name);
    if (is_gzip(bytes, size) && !gzip_allowed)
        return cg_error_set(err, CG_EFORMAT, "%s: gzip data inside gzip data is not read", name);
    if (is_gzip(bytes, size)) {
        unsigned char *plain = NULL;
        size_t plain_size = 0;
        cg_status s = gunzip(bytes, size, name, &plain, &plain_size, err);
        if (s == CG_OK)
            s = load(plain, plain_size, name, format, directory, 0, out, err);
        free(plain);
        return s;
    }
    if (size == 0)
        return cg_error_set(err, CG_EFORMAT, "%s: the file is empty", name);
    const char *foreign = NULL;
    if (format == CG_MESH_FORMAT_AUTO)
        format = sniff(bytes, size);
    if (format == CG_MESH_FORMAT_AUTO && (foreign = mesh_foreign_by_content(bytes, size)))
        return unsupported(name, foreign, "this is", err);
    if (format == CG_MESH_FORMAT_AUTO)
        format = cg_mesh_format_from_path(name);
    if (format == CG_MESH_FORMAT_AUTO && (foreign = mesh_foreign_by_name(name)))
        return unsupported(name, foreign, "the name says this is", err);
    switch (format) {
    case CG_MESH_FORMAT_OBJ: return obj_read((const char *)bytes, size, name, directory, out, err);
    case CG_MESH_FORMAT_OFF: return off_read((const char *)bytes, size, name, out, err);
    case CG_MESH_FORMAT_PLY:
    case CG_MESH_FORMAT_PLY_ASCII:
    case CG_MESH_FORMAT_PLY_BINARY: return ply_read(bytes, size, name, out, err);
    case CG_MESH_FORMAT_STL: return stl_read(bytes, size, name, out, err);
    case CG_MESH_FORMAT_GLTF: return gltf_read(bytes, size, name, directory, out, err);
    case CG_MESH_FORMAT_AUTO: break;
    }
    /* no magic and no known extension: OBJ is the only format without a header */
    if (size >= 2
        && (bytes[0] == 'v' || bytes[0] == '#' || bytes[0] == 'o' || bytes[0] == 'g'
            || bytes[0] == 'm'))
        return obj_read((const char *)bytes, size, name, directory, out, err);
    return cg_error_set(
        err, CG_EFORMAT,
        "%s: unknown mesh format (expected OBJ, OFF, PLY, STL or glTF, by content or "
        "by extension)",
        name);
}

cg_status cg_mesh_load_memory(const void *bytes, size_t size, const char *name,
                              cg_mesh_format format, cg_mesh **out, cg_error *err)
{
    return load(bytes, size, name, format, NULL, 1, out, err);
}

cg_status cg_mesh_load(const char *path, cg_mesh **out, cg_error *err)
{
    if (out)
        *out = NULL;
    if (!path || !out)
        return cg_error_set(err, CG_EINVAL, "mesh load: no path or output given");
    unsigned char *bytes;
    size_t size;
    cg_status s = mesh_read_file(path, &bytes, &size, err);
    if (s != CG_OK)
        return s;
    char *directory = directory_of(path);
    if (!directory)
        s = cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    else
        s = load(bytes, size, path, CG_MESH_FORMAT_AUTO, directory, 1, out, err);
    free(directory);
    free(bytes);
    return s;
}
