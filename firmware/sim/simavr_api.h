/* The few libsimavr entry points the harnesses use. Debian ships libsimavr
 * without headers (libsimavr-dev is a separate package), so they are declared
 * here; they match simavr 1.6 (sim_avr.h, sim_irq.h, sim_elf.h,
 * sim_cycle_timers.h). */
#ifndef MINSEG_SIMAVR_API_H
#define MINSEG_SIMAVR_API_H

#include <stdint.h>

typedef struct avr_t avr_t;
typedef uint64_t avr_cycle_count_t;

/* sim_avr_types.h, sim_irq.h, sim_interrupts.h of simavr 1.6: the harnesses
 * declare one interrupt vector of their own (sim_board.c, pin change on ports J
 * and K), so these three structures are written out as 1.6 lays them out. */
typedef struct avr_regbit_t {
  uint32_t reg : 9, bit : 3, mask : 8;
} avr_regbit_t;
typedef struct avr_irq_t {
  struct avr_irq_pool_t *pool;
  const char *name;
  uint32_t irq;
  uint32_t value;
  uint8_t flags;
  struct avr_irq_hook_t *hook;
} avr_irq_t;
typedef struct avr_int_vector_t {
  uint8_t vector;
  avr_regbit_t enable;
  avr_regbit_t raised;
  avr_irq_t irq[2];
  uint8_t pending : 1, trace : 1, raise_sticky : 1;
} avr_int_vector_t;
/* avr_ioport.h: the level an input pin reads when nothing inside drives it */
typedef struct avr_ioport_external_t {
  unsigned long name : 7, mask : 8, value : 8;
} avr_ioport_external_t;

typedef void (*avr_irq_notify_t)(avr_irq_t *irq, uint32_t value, void *param);
typedef avr_cycle_count_t (*avr_cycle_timer_t)(avr_t *avr, avr_cycle_count_t when, void *param);

avr_t *avr_make_mcu_by_name(const char *name);
int avr_init(avr_t *avr);
int elf_read_firmware(const char *file, void *firmware);
void avr_load_firmware(avr_t *avr, void *firmware);
int avr_run(avr_t *avr);
void avr_reset(avr_t *avr);
avr_irq_t *avr_io_getirq(avr_t *avr, uint32_t ctl, int index);
void avr_irq_register_notify(avr_irq_t *irq, avr_irq_notify_t notify, void *param);
void avr_raise_irq(avr_irq_t *irq, uint32_t value);
int avr_ioctl(avr_t *avr, uint32_t ctl, void *io_param);
void avr_cycle_timer_register_usec(avr_t *avr, uint32_t when, avr_cycle_timer_t timer,
                                   void *param);
void avr_cycle_timer_register(avr_t *avr, avr_cycle_count_t when, avr_cycle_timer_t timer,
                              void *param);
avr_irq_t *avr_iomem_getirq(avr_t *avr, uint16_t addr, const char *name, int index);
void avr_register_vector(avr_t *avr, avr_int_vector_t *vector);
int avr_raise_interrupt(avr_t *avr, avr_int_vector_t *vector);

#define IOCTL_DEF(a, b, c, d) \
  ((((uint32_t)(a)) << 24) | (((uint32_t)(b)) << 16) | (((uint32_t)(c)) << 8) | ((uint32_t)(d)))
#define UART_GETIRQ(n) IOCTL_DEF('u', 'a', 'r', (n))
#define UART_SET_FLAGS(n) IOCTL_DEF('u', 'a', 's', (n))
#define IOPORT_GETIRQ(p) IOCTL_DEF('i', 'o', 'g', (p))
#define IOPORT_SET_EXTERNAL(p) IOCTL_DEF('i', 'o', 'p', (p))
#define AVR_IOMEM_IRQ_ALL 8
enum { UART_IRQ_INPUT = 0, UART_IRQ_OUTPUT = 1 };
enum { cpu_Done = 6, cpu_Crashed = 7 };
/* elf_firmware_t starts with char mmcu[64]; uint32_t frequency; */
#define FW_FREQUENCY_OFFSET 64

#endif
