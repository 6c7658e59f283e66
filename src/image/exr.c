/* OpenEXR reading and writing.  This build of cg has no OpenEXR library
 * (libopenexr-dev was not found when it was configured): every call says so. */
#include "internal.h"
#include "cg/image_float.h"

int cg_exr_supported(void)
{
    return 0;
}

cg_status exr_decode(const unsigned char *bytes, size_t size, const char *name, cg_image **out,
                     cg_error *err)
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
