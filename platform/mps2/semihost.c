/*
 * semihost.c - fw_io.h over ARM semihosting: the program traps with
 * `bkpt 0xab`, r0 naming the operation and r1 pointing at its arguments,
 * and the debugger (here QEMU, -semihosting-config enable=on) performs it on
 * the host.  Operation numbers and argument blocks are from ARM's
 * "Semihosting for AArch32 and AArch64", version 2.0.
 */
#include <string.h>
#include "fw_io.h"

enum {
    SYS_OPEN = 0x01,
    SYS_CLOSE = 0x02,
    SYS_WRITE0 = 0x04,
    SYS_WRITE = 0x05,
    SYS_GET_CMDLINE = 0x15,
    SYS_EXIT = 0x18,
    SYS_EXIT_EXTENDED = 0x20
};
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define OPEN_MODE_WB 5               /* fopen mode "wb" */

static uintptr_t semihost(uintptr_t op, const void *arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    /* The host may read and write memory through r1: a memory clobber. */
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void fw_cmdline(char *buf, size_t size)
{
    uintptr_t block[2] = { (uintptr_t)buf, size };
    if (size == 0) return;
    if (semihost(SYS_GET_CMDLINE, block) != 0) buf[0] = 0;
    buf[size - 1] = 0;
}

int fw_open_write(const char *path)
{
    uintptr_t block[3] = { (uintptr_t)path, OPEN_MODE_WB, strlen(path) };
    return (int)semihost(SYS_OPEN, block);
}

int fw_write(int handle, const void *data, size_t n)
{
    uintptr_t block[3] = { (uintptr_t)handle, (uintptr_t)data, n };
    /* returns the number of bytes NOT written */
    return semihost(SYS_WRITE, block) == 0 ? 0 : -1;
}

int fw_close(int handle)
{
    uintptr_t block[1] = { (uintptr_t)handle };
    return (int)semihost(SYS_CLOSE, block);
}

void fw_print(const char *s)
{
    semihost(SYS_WRITE0, s);
}

void fw_exit(int status)
{
    /* The extended call carries the status; plain SYS_EXIT can only say
     * success or failure, and is the fallback for hosts without it. */
    uintptr_t block[2] = { ADP_STOPPED_APPLICATION_EXIT, (uintptr_t)status };
    semihost(SYS_EXIT_EXTENDED, block);
    semihost(SYS_EXIT, (const void *)(uintptr_t)(status ? 0x20023u : ADP_STOPPED_APPLICATION_EXIT));
    for (;;) {
    }
}
