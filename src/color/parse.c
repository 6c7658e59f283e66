/* Parsing colours from text: hex forms and CSS names. */
#include "cg/color.h"

#include <ctype.h>
#include <string.h>
#include <strings.h>

typedef struct named_color {
    const char *name;
    uint32_t rgb; /* 0xRRGGBB */
} named_color;

/* The CSS basic colour keywords plus a few common extended ones. */
static const named_color named_colors[] = {
    {"black", 0x000000},   {"silver", 0xc0c0c0}, {"gray", 0x808080},    {"grey", 0x808080},
    {"white", 0xffffff},   {"maroon", 0x800000}, {"red", 0xff0000},     {"purple", 0x800080},
    {"fuchsia", 0xff00ff}, {"magenta", 0xff00ff}, {"green", 0x008000},  {"lime", 0x00ff00},
    {"olive", 0x808000},   {"yellow", 0xffff00}, {"navy", 0x000080},    {"blue", 0x0000ff},
    {"teal", 0x008080},    {"aqua", 0x00ffff},   {"cyan", 0x00ffff},    {"orange", 0xffa500},
    {"brown", 0xa52a2a},   {"pink", 0xffc0cb},   {"gold", 0xffd700},    {"indigo", 0x4b0082},
    {"violet", 0xee82ee},  {"darkgray", 0xa9a9a9}, {"lightgray", 0xd3d3d3},
    {"cornflowerblue", 0x6495ed}, {"steelblue", 0x4682b4}, {"skyblue", 0x87ceeb},
    {"crimson", 0xdc143c}, {"coral", 0xff7f50},  {"salmon", 0xfa8072},  {"tomato", 0xff6347},
    {"forestgreen", 0x228b22}, {"darkgreen", 0x006400}, {"darkblue", 0x00008b},
    {"darkred", 0x8b0000}, {"chocolate", 0xd2691e}, {"tan", 0xd2b48c}, {"beige", 0xf5f5dc},
    {"ivory", 0xfffff0},   {"khaki", 0xf0e68c},  {"lavender", 0xe6e6fa}, {"turquoise", 0x40e0d0},
    {"slategray", 0x708090}, {"dimgray", 0x696969}, {"whitesmoke", 0xf5f5f5},
};

static int hex_digit(int c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    c = tolower(c);
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

static cg_status parse_hex(const char *text, cg_rgba8 *out, cg_error *err)
{
    const char *digits = text + 1;
    size_t n = strlen(digits);
    int v[8];
    if (n != 3 && n != 6 && n != 8)
        return cg_error_set(err, CG_EFORMAT,
                            "colour '%s': expected #rgb, #rrggbb or #rrggbbaa", text);
    for (size_t i = 0; i < n; i++) {
        v[i] = hex_digit((unsigned char)digits[i]);
        if (v[i] < 0)
            return cg_error_set(err, CG_EFORMAT, "colour '%s': '%c' is not a hex digit", text,
                                digits[i]);
    }
    if (n == 3) {
        out->r = (uint8_t)(v[0] * 17);
        out->g = (uint8_t)(v[1] * 17);
        out->b = (uint8_t)(v[2] * 17);
        out->a = 255;
    } else {
        out->r = (uint8_t)(v[0] * 16 + v[1]);
        out->g = (uint8_t)(v[2] * 16 + v[3]);
        out->b = (uint8_t)(v[4] * 16 + v[5]);
        out->a = n == 8 ? (uint8_t)(v[6] * 16 + v[7]) : 255;
    }
    return CG_OK;
}

cg_status cg_color_parse(const char *text, cg_rgba8 *out, cg_error *err)
{
    if (!text || !out)
        return cg_error_set(err, CG_EINVAL, "colour: no text given");
    if (text[0] == '#')
        return parse_hex(text, out, err);
    if (strcasecmp(text, "transparent") == 0) {
        cg_rgba8 none = {0, 0, 0, 0};
        *out = none;
        return CG_OK;
    }
    for (size_t i = 0; i < sizeof named_colors / sizeof named_colors[0]; i++) {
        if (strcasecmp(text, named_colors[i].name) == 0) {
            uint32_t rgb = named_colors[i].rgb;
            out->r = (uint8_t)(rgb >> 16);
            out->g = (uint8_t)(rgb >> 8);
            out->b = (uint8_t)rgb;
            out->a = 255;
            return CG_OK;
        }
    }
    return cg_error_set(err, CG_EFORMAT, "unknown colour '%s': expected #rrggbb or a colour name",
                        text);
}
