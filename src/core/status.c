/* Status codes and error details. */
#include "cg/core.h"

#include <stdarg.h>
#include <stdio.h>

const char *cg_status_str(cg_status status)
{
    switch (status) {
    case CG_OK: return "success";
    case CG_EINVAL: return "invalid argument";
    case CG_ENOMEM: return "out of memory";
    case CG_EIO: return "input/output error";
    case CG_EFORMAT: return "malformed input";
    case CG_ERANGE: return "value out of range";
    case CG_ESINGULAR: return "matrix is singular";
    case CG_EUNSUPPORTED: return "not supported";
    case CG_EEMPTY: return "nothing to work on";
    }
    return "unknown status";
}

cg_status cg_error_set(cg_error *err, cg_status status, const char *format, ...)
{
    if (err) {
        va_list args;
        err->status = status;
        va_start(args, format);
        vsnprintf(err->message, sizeof err->message, format, args);
        va_end(args);
    }
    return status;
}

void cg_error_clear(cg_error *err)
{
    if (err) {
        err->status = CG_OK;
        err->message[0] = '\0';
    }
}
