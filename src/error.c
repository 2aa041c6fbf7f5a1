/*
 * error.c - one-line error messages: "name:line: what is wrong".
 */
#include <stdarg.h>
#include <stdio.h>
#include "silk/error.h"

silk_status silk_fail(silk_error *err, silk_status code, const char *name, uint32_t line,
                      const char *fmt, ...)
{
    if (!err) return code;
    err->code = code;
    err->line = line;
    int n;
    if (name && line)
        n = snprintf(err->msg, sizeof err->msg, "%s:%lu: ", name, (unsigned long)line);
    else if (name)
        n = snprintf(err->msg, sizeof err->msg, "%s: ", name);
    else
        n = 0;
    if (n < 0) n = 0;
    if ((size_t)n < sizeof err->msg) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg + n, sizeof err->msg - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return code;
}

const char *silk_status_name(silk_status s)
{
    switch (s) {
    case SILK_OK: return "ok";
    case SILK_ERR_NOMEM: return "out of arena memory";
    case SILK_ERR_PARSE: return "parse error";
    case SILK_ERR_RANGE: return "value out of range";
    case SILK_ERR_ARG: return "bad argument";
    case SILK_ERR_EMPTY: return "nothing to draw";
    case SILK_ERR_IO: return "i/o error";
    }
    return "unknown error";
}
