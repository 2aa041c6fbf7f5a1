/*
 * fw_io.h - what the firmware's scene (fw_main.c) needs from the machine it
 * runs on: a command line, files on the host, a console, an exit status,
 * and the measured stack and static memory.
 *
 * On the MPS2 board these are ARM semihosting calls (semihost.c) and the
 * startup code's stack painting (startup.c); fw_io_host.c implements them
 * with stdio, so the same scene also runs on the host, byte for byte.
 */
#ifndef SILK_FW_IO_H
#define SILK_FW_IO_H

#include <stddef.h>
#include <stdint.h>

/* The command line (QEMU: the kernel's name, then -append's text) into buf,
 * NUL-terminated; "" when there is none. */
void fw_cmdline(char *buf, size_t size);

/* A host file opened for binary writing: a handle >= 0, or -1. */
int fw_open_write(const char *path);
/* 0 when all n bytes were written. */
int fw_write(int handle, const void *data, size_t n);
int fw_close(int handle);

/* A NUL-terminated string on the console. */
void fw_print(const char *s);

/* End the program with this status (0 success). */
#if defined(__GNUC__)
__attribute__((noreturn))
#endif
void fw_exit(int status);

/* A free-running 32-bit tick counter, counting up and wrapping; 0 on a
 * machine without one.  On the MPS2 board it is the CMSDK APB timer 0
 * (timer_cmsdk.c), clocked at 25 MHz: under QEMU's `-icount shift=0`, where
 * one instruction takes exactly 1 ns of virtual time, a tick is 40
 * instructions; on the micro:bit the nRF51's TIMER0 at 16 MHz
 * (timer_nrf51.c), 62.5 instructions.  fw_timer_start() starts it (the
 * startup code calls it). */
void fw_timer_start(void);
uint32_t fw_ticks(void);
/* Exactly n (> 0) passes of a two-instruction loop (subs, bne) on the board,
 * 2n instructions, to check fw_ticks' rate; nothing on the host. */
void fw_spin(uint32_t n);

/* The program itself (fw_main.c); returns the exit status. */
int fw_scene(void);

/* Memory the program measured about itself; zero where it cannot. */
typedef struct fw_mem {
    size_t data, bss;          /* static RAM: initialised and zeroed */
    size_t stack_size;         /* bytes reserved for the stack */
    size_t stack_used;         /* high-water mark, from stack painting */
    size_t ram_size;           /* the RAM budget the program was linked for */
} fw_mem;
void fw_memory(fw_mem *m);

#endif
