#include "base64.h"

#include <stdint.h>
#include <stdlib.h>

static int base64_value(unsigned char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+' || c == '-')
        return 62;
    if (c == '/' || c == '_')
        return 63;
    return -1;
}

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

int core_base64_decode(const char *text, size_t length, int skip_whitespace, unsigned char **out,
                       size_t *out_size)
{
    size_t end = length;
    if (skip_whitespace)
        while (end > 0 && is_space(text[end - 1]))
            end--;
    /* padding '=' only at the end; at most 2 */
    size_t padding = 0;
    while (end > 0 && padding < 2 && text[end - 1] == '=') {
        padding++;
        end--;
    }
    unsigned char *bytes = malloc(end / 4 * 3 + 3);
    if (!bytes)
        return -1;
    size_t n = 0;
    uint32_t accumulator = 0;
    int bits = 0;
    for (size_t i = 0; i < end; i++) {
        if (skip_whitespace && is_space(text[i]))
            continue;
        int v = base64_value((unsigned char)text[i]);
        if (v < 0) {
            free(bytes);
            return 0;
        }
        accumulator = (accumulator << 6) | (uint32_t)v;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            bytes[n++] = (unsigned char)(accumulator >> bits);
        }
    }
    if (bits >= 6) { /* a lone trailing character carries no whole byte */
        free(bytes);
        return 0;
    }
    *out = bytes;
    *out_size = n;
    return 1;
}
