/*
 * silk/error.h - error codes and the one-line error report.
 *
 * Every fallible core function returns a silk_status and, when given a
 * silk_error, fills it with a message that names the input and, for text
 * formats, the line: "bunny.obj:12: face index 300 out of range (252 vertices)".
 */
#ifndef SILK_ERROR_H
#define SILK_ERROR_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum silk_status {
    SILK_OK = 0,
    SILK_ERR_NOMEM = 1,      /* the arena is too small */
    SILK_ERR_PARSE = 2,      /* malformed input */
    SILK_ERR_RANGE = 3,      /* a value does not fit the fixed-point range */
    SILK_ERR_ARG = 4,        /* a bad argument from the caller */
    SILK_ERR_EMPTY = 5,      /* nothing to draw / no geometry */
    SILK_ERR_IO = 6          /* reported by platform code */
} silk_status;

#define SILK_ERROR_MSG 200

typedef struct silk_error {
    silk_status code;
    uint32_t line;           /* 1-based line for text input, 0 when not applicable */
    char msg[SILK_ERROR_MSG];/* complete one-line message, with name and line */
} silk_error;

/* Fill err (if non-NULL) with "name:line: message" (": line" left out when
 * line == 0) and return code. */
silk_status silk_fail(silk_error *err, silk_status code, const char *name, uint32_t line,
                      const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

const char *silk_status_name(silk_status s);

#ifdef __cplusplus
}
#endif

#endif
