/*
 * startup.c - reset and exceptions for the Cortex-M firmware (M0, M3, M4,
 * M7): the vector table, copying .data from flash, zeroing .bss, painting
 * the stack so its high-water mark can be measured, the FPU enabled on a
 * hard-float build, starting the board's tick counter
 * (fw_timer_start, timer_cmsdk.c or timer_nrf51.c), then the program,
 * fw_scene().  Only Thumb-1 instructions: it runs on a Cortex-M0 too.
 *
 * Stack painting: every word of the stack region below the reset handler's
 * own frame is filled with a pattern before the program runs; afterwards the
 * lowest word no longer holding it is as deep as the stack ever reached.
 * The symbols come from mps2.ld.
 */
#include <stdint.h>
#include <string.h>
#include "fw_io.h"

#define STACK_PAINT 0xC5C5C5C5u

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _sstack, _estack;
extern uint32_t __ram_size;          /* --defsym: the budget, as an address */

void Reset_Handler(void);
void Fault_Handler(void);

void Reset_Handler(void)
{
#if defined(__ARM_FP)
    /* A part with an FPU built for the hard-float ABI (Cortex-M4F, M7):
     * coprocessors 10 and 11 on (CPACR) before anything else runs; the
     * core has no floating point, but the compiler may move data through
     * the FPU's registers and libc may use them. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    uint32_t *src = &_sidata;
    for (uint32_t *dst = &_sdata; dst < &_edata;) *dst++ = *src++;
    for (uint32_t *dst = &_sbss; dst < &_ebss;) *dst++ = 0;
    /* Leave the words this function may itself be using alone. */
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (uint32_t *p = &_sstack; p < sp - 16; p++) *p = STACK_PAINT;
    fw_timer_start();
    fw_exit(fw_scene());
}

void Fault_Handler(void)
{
    fw_print("fw: fault (hard fault, bus or usage fault): stopped\n");
    fw_exit(3);
}

/* Initial stack pointer, reset, then 14 system exceptions (the Cortex-M0
 * reserves the slots of MemManage, BusFault, UsageFault and DebugMon); the
 * scene uses no interrupts, so every exception is a fault here. */
__attribute__((section(".vectors"), used)) static const uintptr_t vectors[16] = {
    (uintptr_t)&_estack, (uintptr_t)Reset_Handler, (uintptr_t)Fault_Handler, (uintptr_t)Fault_Handler,
    (uintptr_t)Fault_Handler, (uintptr_t)Fault_Handler, (uintptr_t)Fault_Handler, 0, 0, 0, 0,
    (uintptr_t)Fault_Handler, (uintptr_t)Fault_Handler, 0, (uintptr_t)Fault_Handler, (uintptr_t)Fault_Handler,
};

void fw_memory(fw_mem *m)
{
    memset(m, 0, sizeof *m);
    m->data = (size_t)((uintptr_t)&_edata - (uintptr_t)&_sdata);
    m->bss = (size_t)((uintptr_t)&_ebss - (uintptr_t)&_sbss);
    m->stack_size = (size_t)((uintptr_t)&_estack - (uintptr_t)&_sstack);
    m->ram_size = (size_t)(uintptr_t)&__ram_size;
    const uint32_t *p = &_sstack;
    while (p < &_estack && *p == STACK_PAINT) p++;
    m->stack_used = (size_t)((uintptr_t)&_estack - (uintptr_t)p);
}

void fw_spin(uint32_t n)
{
    __asm__ volatile(".syntax unified\n1:\tsubs %0, %0, #1\n\tbne 1b" : "+r"(n) : : "cc");
}
