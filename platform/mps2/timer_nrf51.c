/*
 * timer_nrf51.c - fw_ticks() on the nRF51 (BBC micro:bit): TIMER0
 * (0x40008000) in timer mode, 32 bits, prescaler 0, so it counts the 16 MHz
 * clock.  Its counter is read by capturing it into CC[0] (nRF51 Series
 * Reference Manual, chapter "TIMER").  Under QEMU with `-icount shift=0`
 * one instruction is one nanosecond of virtual time, so a tick is 62.5
 * instructions; QEMU's model carries the fraction from one update to the
 * next, so over many ticks the count is exact to one tick.
 */
#include "fw_io.h"

#define TIMER0 0x40008000u
#define REG(off) (*(volatile uint32_t *)(TIMER0 + (off)))
#define TASKS_START REG(0x000)
#define TASKS_CLEAR REG(0x00C)
#define TASKS_CAPTURE0 REG(0x040)
#define MODE REG(0x504)                /* 0: timer */
#define BITMODE REG(0x508)             /* 3: 32 bits */
#define PRESCALER REG(0x510)           /* f = 16 MHz / 2^PRESCALER */
#define CC0 REG(0x540)

void fw_timer_start(void)
{
    MODE = 0;
    BITMODE = 3;
    PRESCALER = 0;
    TASKS_CLEAR = 1;
    TASKS_START = 1;
}

uint32_t fw_ticks(void)
{
    TASKS_CAPTURE0 = 1;
    return CC0;
}
