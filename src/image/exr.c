/* OpenEXR through OpenEXRCore, the C API of OpenEXR 3 (Debian
 * libopenexr-dev).  Files are decoded from and encoded into memory through
 * the library's custom stream callbacks, so that writing stays atomic (the
 * bytes go to disk through image_replace_file).  Reading takes the R, G, B,
 * A (or Y) channels of the first part, scanline or tiled (level 0), into
 * RGBAF; a missing A reads as 1, Y fills R, G and B.  Without the library
 * (CG_HAVE_OPENEXR unset) every call fails with CG_EUNSUPPORTED. */
#include "internal.h"
#include "cg/image_float.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef CG_HAVE_OPENEXR
#include <openexr.h>

/* The stream of one context: the bytes read from or written into, and the
 * library's last error message. */
typedef struct memory_stream {
    const unsigned char *in;
    size_t in_size;
    byte_buffer *out;
    char message[160];
} memory_stream;

static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    void *user = NULL;
    (void)code;
    if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user && msg) {
        memory_stream *s = user;
        snprintf(s->message, sizeof s->message, "%s", msg);
    }
}

static int64_t stream_read(exr_const_context_t ctxt, void *user, void *buffer, uint64_t size,
                           uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    memory_stream *s = user;
    (void)ctxt;
    (void)error_cb;
    if (offset >= s->in_size)
        return 0;
    uint64_t n = s->in_size - offset < size ? s->in_size - offset : size;
    memcpy(buffer, s->in + offset, (size_t)n);
    return (int64_t)n;
}

static int64_t stream_size(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return (int64_t)((memory_stream *)user)->in_size;
}

static int64_t stream_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t size,
                            uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    memory_stream *s = user;
    (void)ctxt;
    (void)error_cb;
    byte_buffer *b = s->out;
    if (offset > SIZE_MAX / 2 || size > SIZE_MAX / 2)
        return -1;
    size_t end = (size_t)offset + (size_t)size;
    if (end > b->size) {
        static const unsigned char zeros[256];
        while (b->size < offset) {
            size_t gap = (size_t)offset - b->size;
            if (byte_buffer_append(b, zeros, gap < sizeof zeros ? gap : sizeof zeros) != CG_OK)
                return -1;
        }
        size_t tail = end - b->size; /* the part beyond the current end */
        if (byte_buffer_append(b, (const unsigned char *)buffer + (size - tail), tail) != CG_OK)
            return -1;
        size -= tail;
    }
    if (size > 0)
        memcpy(b->bytes + offset, buffer, (size_t)size);
    return (int64_t)(end - (size_t)offset);
}

static cg_status fail_exr(exr_result_t rv, const memory_stream *s, const char *name,
                          const char *what, cg_status status, cg_error *err)
{
    const char *why = s->message[0] ? s->message : exr_get_default_error_message(rv);
    return cg_error_set(err, status, "%s: %s: %s", name, what, why);
}

int cg_exr_supported(void)
{
    return 1;
}

/* ---- reading ------------------------------------------------------------- */

/* Which RGBAF component (0..3) a channel fills, 4 for Y, -1 for none. */
static int channel_slot(const char *name)
{
    static const char *const names[] = {"R", "G", "B", "A", "Y"};
    for (int k = 0; k < 5; k++)
        if (strcmp(name, names[k]) == 0)
            return k;
    return -1;
}

/* The plane of one chunk that receives the channels cg does not keep;
 * planes 0-4 are R, G, B, A and Y (channel_slot). */
enum { DISCARD_PLANE = 5 };

typedef struct read_state {
    exr_context_t ctx;
    exr_decode_pipeline_t decoder;
    int decoder_ready;
    exr_attr_box2i_t window;
    cg_image *image;
    int grey;      /* the file has Y and not R, G, B */
    float *planes; /* the planes of one chunk: R, G, B, A, Y, discard */
    size_t planes_pixels;
} read_state;

/* Copies the decoded planes of a w x h chunk at (x0, y0) into the image. */
static void scatter_chunk(read_state *r, int x0, int y0, int w, int h, int present)
{
    size_t n = (size_t)w * (size_t)h;
    for (int y = 0; y < h; y++) {
        cg_rgbaf *row = cg_image_row_rgbaf(r->image, y0 + y) + x0;
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            float *p = r->planes + i;
            if (r->grey && (present & 16))
                row[x].r = row[x].g = row[x].b = p[4 * n];
            for (int k = 0; k < 4 && !r->grey; k++)
                if (present & (1 << k))
                    (&row[x].r)[k] = p[(size_t)k * n];
            if (r->grey && (present & 8))
                row[x].a = p[3 * n];
        }
    }
}

/* Decodes one chunk whose top-left pixel is (x0, y0) of the data window;
 * each channel into a plane of its own, then into the image. */
static exr_result_t decode_chunk(read_state *r, const exr_chunk_info_t *chunk, int x0, int y0)
{
    int w = chunk->width, h = chunk->height;
    if (w <= 0 || h <= 0 || x0 + (int64_t)w > r->image->width || y0 + (int64_t)h > r->image->height
        || x0 < 0 || y0 < 0)
        return EXR_ERR_CORRUPT_CHUNK;
    size_t n = (size_t)w * (size_t)h;
    if (n > r->planes_pixels) {
        free(r->planes);
        r->planes_pixels = 0;
        if (!(r->planes = malloc((DISCARD_PLANE + 1) * n * sizeof *r->planes)))
            return EXR_ERR_OUT_OF_MEMORY;
        r->planes_pixels = n;
    }
    exr_result_t rv = r->decoder_ready ? exr_decoding_update(r->ctx, 0, chunk, &r->decoder)
                                       : exr_decoding_initialize(r->ctx, 0, chunk, &r->decoder);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    int first = !r->decoder_ready, present = 0;
    r->decoder_ready = 1;
    for (int c = 0; c < r->decoder.channel_count; c++) {
        exr_coding_channel_info_t *ch = &r->decoder.channels[c];
        int slot = channel_slot(ch->channel_name);
        /* Every channel gets a destination: OpenEXRCore 3.1 writes through a
         * NULL decode_to_ptr on some corrupt chunks.  Channels cg does not
         * keep (and any of a size other than the chunk's, at most w x h)
         * all go to the discard plane. */
        if (slot < 0 || ch->height != h || ch->width != w)
            slot = DISCARD_PLANE;
        else
            present |= 1 << slot;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = 4;
        ch->user_line_stride = 4 * (ch->width > 0 ? ch->width : 1);
        ch->decode_to_ptr = (uint8_t *)(r->planes + (size_t)slot * n);
    }
    if (first
        && (rv = exr_decoding_choose_default_routines(r->ctx, 0, &r->decoder)) != EXR_ERR_SUCCESS)
        return rv;
    if ((rv = exr_decoding_run(r->ctx, 0, &r->decoder)) == EXR_ERR_SUCCESS)
        scatter_chunk(r, x0, y0, w, h, present);
    return rv;
}

static exr_result_t read_scanlines(read_state *r)
{
    int32_t lines;
    exr_result_t rv = exr_get_scanlines_per_chunk(r->ctx, 0, &lines);
    for (int64_t y = r->window.min.y; rv == EXR_ERR_SUCCESS && y <= r->window.max.y; y += lines) {
        exr_chunk_info_t chunk;
        rv = exr_read_scanline_chunk_info(r->ctx, 0, (int)y, &chunk);
        if (rv == EXR_ERR_SUCCESS)
            rv = decode_chunk(r, &chunk, 0, chunk.start_y - r->window.min.y);
    }
    return rv;
}

static exr_result_t read_tiles(read_state *r)
{
    uint32_t tw, th;
    exr_tile_level_mode_t level;
    exr_tile_round_mode_t round;
    exr_result_t rv = exr_get_tile_descriptor(r->ctx, 0, &tw, &th, &level, &round);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    if (level == EXR_TILE_RIPMAP_LEVELS || tw == 0 || th == 0)
        return EXR_ERR_FEATURE_NOT_IMPLEMENTED;
    int64_t w = r->image->width, h = r->image->height;
    for (int64_t ty = 0; rv == EXR_ERR_SUCCESS && ty * th < h; ty++)
        for (int64_t tx = 0; rv == EXR_ERR_SUCCESS && tx * tw < w; tx++) {
            exr_chunk_info_t chunk;
            rv = exr_read_tile_chunk_info(r->ctx, 0, (int)tx, (int)ty, 0, 0, &chunk);
            if (rv == EXR_ERR_SUCCESS)
                rv = decode_chunk(r, &chunk, (int)(tx * tw), (int)(ty * th));
        }
    return rv;
}

/* Checks the part's kind and channels; *grey set when it is a Y image. */
static cg_status check_part(read_state *r, memory_stream *s, const char *name, int *grey,
                            cg_error *err)
{
    exr_storage_t storage;
    const exr_attr_chlist_t *channels;
    exr_result_t rv = exr_get_storage(r->ctx, 0, &storage);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_channels(r->ctx, 0, &channels);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_data_window(r->ctx, 0, &r->window);
    if (rv != EXR_ERR_SUCCESS)
        return fail_exr(rv, s, name, "bad OpenEXR header", CG_EFORMAT, err);
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return cg_error_set(err, CG_EUNSUPPORTED, "%s: deep OpenEXR images are not supported",
                            name);
    int found = 0;
    for (int c = 0; c < channels->num_channels; c++) {
        const exr_attr_chlist_entry_t *e = &channels->entries[c];
        int slot = channel_slot(e->name.str);
        if (slot < 0)
            continue;
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return cg_error_set(err, CG_EUNSUPPORTED,
                                "%s: subsampled OpenEXR channel '%s' is not supported", name,
                                e->name.str);
        found |= 1 << slot;
    }
    *grey = (found & 7) != 7 && (found & 16);
    if ((found & 7) != 7 && !*grey)
        return cg_error_set(err, CG_EFORMAT,
                            "%s: OpenEXR file has no R, G, B or Y channels in its first part",
                            name);
    int64_t w = (int64_t)r->window.max.x - r->window.min.x + 1;
    int64_t h = (int64_t)r->window.max.y - r->window.min.y + 1;
    if (w <= 0 || h <= 0)
        return cg_error_set(err, CG_EFORMAT, "%s: OpenEXR data window is empty", name);
    return image_check_dimensions((unsigned long)w, (unsigned long)h, name, err);
}

static cg_status decode_pixels(read_state *r, memory_stream *s, const char *name, cg_error *err)
{
    int w = r->window.max.x - r->window.min.x + 1, h = r->window.max.y - r->window.min.y + 1;
    if (cg_image_create(&r->image, w, h, CG_PIXEL_RGBAF) != CG_OK)
        return cg_error_set(err, CG_ENOMEM, "%s: cannot allocate %d x %d image", name, w, h);
    cg_image_clear(r->image, (cg_rgbaf){0, 0, 0, 1});
    exr_storage_t storage;
    exr_get_storage(r->ctx, 0, &storage);
    exr_result_t rv = storage == EXR_STORAGE_TILED ? read_tiles(r) : read_scanlines(r);
    if (rv != EXR_ERR_SUCCESS)
        return fail_exr(rv, s, name, "corrupt or truncated OpenEXR data", CG_EFORMAT, err);
    return CG_OK;
}

cg_status image_exr_decode(const unsigned char *bytes, size_t size, const char *name,
                           cg_image **out, cg_error *err)
{
    *out = NULL;
    memory_stream s = {bytes, size, NULL, ""};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &s;
    init.read_fn = stream_read;
    init.size_fn = stream_size;
    init.error_handler_fn = on_error;
    init.max_image_width = init.max_image_height = CG_IMAGE_MAX_SIDE;
    init.max_tile_width = init.max_tile_height = 1 << 16;
    read_state r = {0};
    exr_result_t rv = exr_start_read(&r.ctx, name, &init);
    if (rv != EXR_ERR_SUCCESS) {
        exr_finish(&r.ctx);
        return fail_exr(rv, &s, name, "bad OpenEXR header", CG_EFORMAT, err);
    }
    cg_status status = check_part(&r, &s, name, &r.grey, err);
    if (status == CG_OK)
        status = decode_pixels(&r, &s, name, err);
    if (r.decoder_ready)
        exr_decoding_destroy(r.ctx, &r.decoder);
    exr_finish(&r.ctx);
    free(r.planes);
    if (status != CG_OK)
        cg_image_free(r.image);
    else
        *out = r.image;
    return status;
}

/* ---- writing ------------------------------------------------------------- */

/* One output channel: its name and where its floats come from. */
typedef struct channel_source {
    char name[80];
    const cg_image *image;
    int component;
} channel_source;

static cg_status layer_sources(const cg_image *beauty, const cg_image_layer *extra, size_t n,
                               channel_source *sources, size_t *count, const char *path,
                               cg_error *err)
{
    static const char rgba[] = "RGBA";
    for (int k = 0; k < 4; k++)
        sources[(*count)++] = (channel_source){{rgba[k], '\0'}, beauty, k};
    for (size_t i = 0; i < n; i++) {
        const cg_image_layer *l = &extra[i];
        size_t len = l->name ? strlen(l->name) : 0;
        size_t m = l->suffixes ? strlen(l->suffixes) : 0;
        if (len == 0 || len > 60
            || strspn(l->name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRST"
                               "UVWXYZ0123456789_-")
                   != len)
            return cg_error_set(err, CG_EINVAL, "%s: EXR layer %zu: bad name", path, i);
        if (m < 1 || m > 4)
            return cg_error_set(err, CG_EINVAL, "%s: EXR layer '%s': 1 to 4 channel suffixes", path,
                                l->name);
        if (!l->image || l->image->format != CG_PIXEL_RGBAF || l->image->width != beauty->width
            || l->image->height != beauty->height)
            return cg_error_set(err, CG_EINVAL,
                                "%s: EXR layer '%s' is not an RGBAF image of %d x %d pixels", path,
                                l->name, beauty->width, beauty->height);
        for (size_t k = 0; k < m; k++) {
            channel_source *src = &sources[*count];
            snprintf(src->name, sizeof src->name, "%s.%c", l->name, l->suffixes[k]);
            for (size_t j = 0; j < *count; j++)
                if (strcmp(sources[j].name, src->name) == 0)
                    return cg_error_set(err, CG_EINVAL, "%s: EXR channel '%s' given twice", path,
                                        src->name);
            src->image = l->image;
            src->component = (int)k;
            (*count)++;
        }
    }
    return CG_OK;
}

static exr_result_t encode_rows(exr_context_t ctx, const channel_source *sources, size_t count,
                                int height)
{
    int32_t lines;
    exr_encode_pipeline_t encoder;
    int ready = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < height; y += lines) {
        exr_chunk_info_t chunk;
        if ((rv = exr_write_scanline_chunk_info(ctx, 0, y, &chunk)) != EXR_ERR_SUCCESS)
            break;
        rv = ready ? exr_encoding_update(ctx, 0, &chunk, &encoder)
                   : exr_encoding_initialize(ctx, 0, &chunk, &encoder);
        if (rv != EXR_ERR_SUCCESS)
            break;
        int first = !ready;
        ready = 1;
        for (int c = 0; c < encoder.channel_count; c++) {
            exr_coding_channel_info_t *ch = &encoder.channels[c];
            const channel_source *src = sources;
            for (size_t k = 0; k < count; k++)
                if (strcmp(sources[k].name, ch->channel_name) == 0)
                    src = &sources[k];
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = (int32_t)sizeof(cg_rgbaf);
            ch->user_line_stride = (int32_t)src->image->stride;
            ch->encode_from_ptr = src->image->data + (size_t)chunk.start_y * src->image->stride
                                  + 4 * (size_t)src->component;
        }
        if (first
            && (rv = exr_encoding_choose_default_routines(ctx, 0, &encoder)) != EXR_ERR_SUCCESS)
            break;
        rv = exr_encoding_run(ctx, 0, &encoder);
    }
    if (ready)
        exr_encoding_destroy(ctx, &encoder);
    return rv;
}

static cg_status encode_file(const channel_source *sources, size_t count, int width, int height,
                             int full_float, byte_buffer *out, const char *path, cg_error *err)
{
    memory_stream s = {NULL, 0, out, ""};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &s;
    init.write_fn = stream_write;
    init.error_handler_fn = on_error;
    exr_context_t ctx = NULL;
    int part;
    exr_result_t rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctx, 0, width, height, EXR_COMPRESSION_ZIP);
    for (size_t k = 0; rv == EXR_ERR_SUCCESS && k < count; k++)
        rv = exr_add_channel(ctx, 0, sources[k].name, full_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF,
                             EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_write_header(ctx);
    if (rv == EXR_ERR_SUCCESS)
        rv = encode_rows(ctx, sources, count, height);
    exr_result_t done = exr_finish(&ctx);
    if (rv == EXR_ERR_SUCCESS)
        rv = done;
    if (rv != EXR_ERR_SUCCESS)
        return fail_exr(rv, &s, path, "cannot encode OpenEXR", CG_EIO, err);
    return CG_OK;
}

cg_status cg_image_write_exr(const char *path, const cg_image *beauty, const cg_image_layer *extra,
                             size_t n, const cg_exr_options *options, cg_error *err)
{
    if (!path || !beauty || (n > 0 && !extra))
        return cg_error_set(err, CG_EINVAL, "EXR write: no path, image or layers given");
    if (n > 64)
        return cg_error_set(err, CG_EINVAL, "%s: at most 64 EXR layers, got %zu", path, n);
    cg_image *linear = NULL;
    if (beauty->format != CG_PIXEL_RGBAF) {
        if (cg_image_decode_srgb(beauty, &linear) != CG_OK)
            return cg_error_set(err, CG_ENOMEM, "%s: cannot convert the image for writing", path);
        beauty = linear;
    }
    channel_source sources[4 + 64 * 4];
    size_t count = 0;
    cg_status status = layer_sources(beauty, extra, n, sources, &count, path, err);
    byte_buffer contents = {0};
    if (status == CG_OK)
        status = encode_file(sources, count, beauty->width, beauty->height,
                             options && options->full_float, &contents, path, err);
    if (status == CG_OK)
        status = image_replace_file(path, &contents, err);
    byte_buffer_free(&contents);
    cg_image_free(linear);
    return status;
}

#else /* no OpenEXR */

int cg_exr_supported(void)
{
    return 0;
}

cg_status image_exr_decode(const unsigned char *bytes, size_t size, const char *name,
                           cg_image **out, cg_error *err)
{
    (void)bytes;
    (void)size;
    *out = NULL;
    return cg_error_set(err, CG_EUNSUPPORTED,
                        "%s: cannot read OpenEXR: cg was built without OpenEXR (libopenexr-dev)",
                        name);
}

cg_status cg_image_write_exr(const char *path, const cg_image *beauty, const cg_image_layer *extra,
                             size_t n, const cg_exr_options *options, cg_error *err)
{
    (void)beauty;
    (void)extra;
    (void)n;
    (void)options;
    return cg_error_set(err, CG_EUNSUPPORTED,
                        "%s: cannot write OpenEXR: cg was built without OpenEXR (libopenexr-dev)",
                        path ? path : "image");
}
#endif
