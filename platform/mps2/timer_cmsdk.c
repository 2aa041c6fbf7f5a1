/*
 * timer_cmsdk.c - fw_ticks() on the MPS2 board: the CMSDK APB timer 0
 * (0x40000000, clocked by the 25 MHz system clock) runs free from reload
 * 0xFFFFFFFF; fw_ticks() returns its count inverted, so it counts up.  It
 * is 32 bits wide (SysTick has 24, which wrap after 0.67 s at 25 MHz), so a
 * frame never wraps it twice.  Under QEMU with `-icount shift=0` virtual
 * time is one nanosecond per instruction, so one tick is exactly 40
 * instructions.
 */
#include "fw_io.h"

/* control (bit 0 enable), current value, reload */
#define TIMER0_CTRL (*(volatile uint32_t *)0x40000000u)
#define TIMER0_VALUE (*(volatile uint32_t *)0x40000004u)
#define TIMER0_RELOAD (*(volatile uint32_t *)0x40000008u)

void fw_timer_start(void)
{
    TIMER0_RELOAD = 0xFFFFFFFFu;
    TIMER0_VALUE = 0xFFFFFFFFu;
    TIMER0_CTRL = 1u;
}

uint32_t fw_ticks(void)
{
    return ~TIMER0_VALUE;
}
