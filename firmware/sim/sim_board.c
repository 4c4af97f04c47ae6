/* The simulated board both simavr harnesses drive; see sim_board.h. */
#include "sim_board.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static avr_t *avr;
static avr_irq_t *uart_in;
static uint32_t uart_flags; /* 0: no echo of the UART output to stdout */
static uint64_t now_us;     /* simulated time, advanced by a 100 us cycle timer */

/* the line being received, and where complete lines go */
static char cur[SIM_LINE_CAP];
static size_t cur_len;
static sim_line_fn line_sink;

/* pins driven from outside: per port 'A'..'L', which and to what level */
static uint8_t ext_mask[12], ext_value[12];

/* pin change interrupts on ports J and K, missing from simavr 1.6 */
#define R_PCIFR 0x3B
#define R_PCICR 0x68
#define R_PCMSK1 0x6C
#define R_PCMSK2 0x6D
static avr_int_vector_t pcint1 = {.vector = 10, /* PCINT1_vect */
                                  .enable = {.reg = R_PCICR, .bit = 1, .mask = 1},
                                  .raised = {.reg = R_PCIFR, .bit = 1, .mask = 1}};
static avr_int_vector_t pcint2 = {.vector = 11, /* PCINT2_vect */
                                  .enable = {.reg = R_PCICR, .bit = 2, .mask = 1},
                                  .raised = {.reg = R_PCIFR, .bit = 2, .mask = 1}};
static uint8_t pcmsk1, pcmsk2; /* as last written by the firmware */

static void on_pcmsk(avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  *(uint8_t *)param = (uint8_t)value;
}

/* a pin of port J (PJn is PCINTn+9, PCMSK1 bit n+1) or K (PKn: PCMSK2 bit n) changed */
static void on_pin_j(avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  (void)value;
  int bit = (int)(intptr_t)param;
  if (pcmsk1 & (1u << (bit + 1))) avr_raise_interrupt(avr, &pcint1);
}
static void on_pin_k(avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  (void)value;
  int bit = (int)(intptr_t)param;
  if (pcmsk2 & (1u << bit)) avr_raise_interrupt(avr, &pcint2);
}

static void add_pcint_jk(void) {
  avr_register_vector(avr, &pcint1);
  avr_register_vector(avr, &pcint2);
  avr_irq_register_notify(avr_iomem_getirq(avr, R_PCMSK1, NULL, AVR_IOMEM_IRQ_ALL), on_pcmsk,
                          &pcmsk1);
  avr_irq_register_notify(avr_iomem_getirq(avr, R_PCMSK2, NULL, AVR_IOMEM_IRQ_ALL), on_pcmsk,
                          &pcmsk2);
  for (int b = 0; b < 8; ++b) {
    if (b < 7)
      avr_irq_register_notify(avr_io_getirq(avr, IOPORT_GETIRQ('J'), b), on_pin_j,
                              (void *)(intptr_t)b);
    avr_irq_register_notify(avr_io_getirq(avr, IOPORT_GETIRQ('K'), b), on_pin_k,
                            (void *)(intptr_t)b);
  }
}

avr_irq_t *sim_pin_irq(char port, int bit) { return avr_io_getirq(avr, IOPORT_GETIRQ(port), bit); }

void sim_pin_set(char port, int bit, int level) {
  int p = port - 'A';
  ext_mask[p] |= (uint8_t)(1u << bit);
  if (level) ext_value[p] |= (uint8_t)(1u << bit);
  else ext_value[p] &= (uint8_t)~(1u << bit);
  avr_ioport_external_t e = {.name = (unsigned long)port, .mask = ext_mask[p],
                             .value = ext_value[p]};
  avr_ioctl(avr, IOPORT_SET_EXTERNAL(port), &e);
  avr_raise_irq(sim_pin_irq(port, bit), (uint32_t)(level != 0));
}

/* bytes waiting to go to the board, paced by tick */
static unsigned char tx[SIM_SEND_CAP];
static size_t tx_len, tx_pos;

static void on_uart_byte(avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  (void)param;
  char c = (char)value;
  if (c == '\n') {
    cur[cur_len] = '\0';
    line_sink(cur);
    cur_len = 0;
  } else if (cur_len < SIM_LINE_CAP - 1) {
    cur[cur_len++] = c;
  }
}

static avr_cycle_count_t tick(avr_t *a, avr_cycle_count_t when, void *param) {
  (void)a;
  (void)param;
  now_us += 100;
  for (int k = 0; k < 2 && tx_pos < tx_len; ++k) avr_raise_irq(uart_in, tx[tx_pos++]);
  return when + 1600; /* 100 us at 16 MHz */
}

avr_t *sim_board_boot(const char *elf_path, sim_line_fn on_line) {
  static unsigned char fw[1 << 16]; /* elf_firmware_t, zero-initialised */
  if (elf_read_firmware(elf_path, fw) != 0) {
    fprintf(stderr, "cannot read %s\n", elf_path);
    return NULL;
  }
  uint32_t freq = 16000000u;
  memcpy(fw + FW_FREQUENCY_OFFSET, &freq, sizeof freq);
  avr = avr_make_mcu_by_name("atmega2560");
  if (!avr) {
    fprintf(stderr, "simavr has no atmega2560 core\n");
    return NULL;
  }
  avr_init(avr);
  avr_load_firmware(avr, fw);
  line_sink = on_line;
  avr_irq_register_notify(avr_io_getirq(avr, UART_GETIRQ('0'), UART_IRQ_OUTPUT), on_uart_byte,
                          NULL);
  uart_in = avr_io_getirq(avr, UART_GETIRQ('0'), UART_IRQ_INPUT);
  avr_ioctl(avr, UART_SET_FLAGS('0'), &uart_flags);
  avr_cycle_timer_register_usec(avr, 100, tick, NULL);
  add_pcint_jk();
  return avr;
}

void sim_board_reset(void) {
  avr_reset(avr);
  avr_ioctl(avr, UART_SET_FLAGS('0'), &uart_flags);
  avr_cycle_timer_register_usec(avr, 100, tick, NULL); /* a reset clears the timers */
  pcmsk1 = pcmsk2 = 0;                                 /* and the registers */
  cur_len = 0;
  tx_len = tx_pos = 0;
}

uint64_t sim_now_us(void) { return now_us; }

void sim_run_until_us(uint64_t t_us) {
  while (now_us < t_us) {
    int st = avr_run(avr);
    if (st == cpu_Done || st == cpu_Crashed) {
      printf("FAIL: simulated CPU stopped (state %d)\n", st);
      exit(1);
    }
  }
}

void sim_run_for_us(uint64_t us) { sim_run_until_us(now_us + us); }

void sim_send(const char *s) {
  for (const char *p = s; *p; ++p) avr_raise_irq(uart_in, (uint8_t)*p);
}

void sim_send_paced(const unsigned char *bytes, size_t n) {
  if (n > sizeof tx) {
    printf("FAIL: %zu bytes to send at once, at most %zu\n", n, sizeof tx);
    exit(1);
  }
  memcpy(tx, bytes, n);
  tx_len = n;
  tx_pos = 0;
  while (tx_pos < tx_len) sim_run_for_us(100);
}

unsigned sim_crc16(const char *s, size_t n) {
  unsigned crc = 0xFFFF;
  for (size_t i = 0; i < n; ++i) {
    crc ^= (unsigned)(unsigned char)s[i] << 8;
    for (int b = 0; b < 8; ++b)
      crc = (crc & 0x8000u) ? ((crc << 1) ^ 0x1021u) & 0xFFFFu : (crc << 1) & 0xFFFFu;
  }
  return crc;
}

int sim_checksum_ok(const char *line) {
  const char *star = strrchr(line, '*');
  if (line[0] != '$' || !star || strlen(star) != 5) return 0;
  char hex[8];
  snprintf(hex, sizeof hex, "%04X", sim_crc16(line + 1, (size_t)(star - line - 1)));
  return strcmp(hex, star + 1) == 0;
}
