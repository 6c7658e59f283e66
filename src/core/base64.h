/* Private to libcg: base64 (RFC 4648, with its URL-safe alphabet too), the
 * payload of data: URIs in glTF buffers and images and in SVG images. */
#ifndef CG_CORE_BASE64_H
#define CG_CORE_BASE64_H

#include <stddef.h>

/* Decodes length characters of text into a new malloc'ed block (*out, its
 * size in *out_size): '=' padding only at the end (at most two), and with
 * skip_whitespace, spaces, tabs and line breaks anywhere ignored (SVG data
 * URIs are often wrapped).  1 on success, 0 when the text is not base64
 * (a character outside the alphabet, or a lone trailing character that
 * carries no whole byte), -1 when memory runs out.  *out is set only on 1. */
int core_base64_decode(const char *text, size_t length, int skip_whitespace, unsigned char **out,
                       size_t *out_size);

#endif
