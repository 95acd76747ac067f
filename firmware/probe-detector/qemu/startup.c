/* Bare-metal start for QEMU's MPS2 boards (Cortex-M4F, M7, M33): the vector
 * table, the FPU switched on before the first float instruction, .data and
 * .bss set up, newlib's semihosting (librdimon) opened, main run, its
 * status handed to QEMU. A fault ends the run with status 1 instead of the
 * hang a bare-metal fault is; the test runs QEMU under a timeout anyway. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern uint32_t __stack_top, __data_load, __data_start, __data_end, __bss_start, __bss_end;
extern void initialise_monitor_handles(void);
extern int main(void);

/* Semihosting SYS_EXIT with "run-time error": QEMU exits non-zero. */
static void fail_to_host(void)
{
    register uint32_t op __asm__("r0") = 0x18;        /* SYS_EXIT */
    register uint32_t reason __asm__("r1") = 0x20023; /* ADP_Stopped_RunTimeErrorUnknown */
    __asm__ volatile("bkpt 0xab" : : "r"(op), "r"(reason) : "memory");
    for (;;) {
    }
}

void Fault_Handler(void)
{
    fail_to_host();
}

void Reset_Handler(void)
{
    /* CPACR: full access to CP10 and CP11, the FPU. */
    volatile uint32_t* cpacr = (volatile uint32_t*)0xE000ED88u;
    *cpacr |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" : : : "memory");
    memcpy(&__data_start, &__data_load, (size_t)((char*)&__data_end - (char*)&__data_start));
    memset(&__bss_start, 0, (size_t)((char*)&__bss_end - (char*)&__bss_start));
    initialise_monitor_handles();
    exit(main());
}

/* Initial stack, reset, then NMI, HardFault, MemManage, BusFault, UsageFault, SecureFault. */
__attribute__((section(".vectors"), used)) static void (*const vectors[])(void) = {
    (void (*)(void))(&__stack_top),
    Reset_Handler,
    Fault_Handler,
    Fault_Handler,
    Fault_Handler,
    Fault_Handler,
    Fault_Handler,
    Fault_Handler,
};
