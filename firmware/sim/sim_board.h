/* The simulated board both simavr harnesses drive: the firmware ELF booted on
 * an ATmega2560 at 16 MHz, UART0 wired to the harness, simulated time kept by
 * a 100 us cycle timer, and the frame checksum of PROTOCOL.md. One board per
 * process (the state is static in sim_board.c). */
#ifndef MINSEG_SIM_BOARD_H
#define MINSEG_SIM_BOARD_H

#include <stddef.h>
#include <stdint.h>

#include "simavr_api.h"

/* size of a line buffer: the collector keeps the first SIM_LINE_CAP - 1 bytes
 * of a line and drops the rest */
#define SIM_LINE_CAP 400
/* the most bytes sim_send_paced takes at once: a line and its \r\n */
#define SIM_SEND_CAP (SIM_LINE_CAP + 2)

/* called with each line the board sends, without its '\n' */
typedef void (*sim_line_fn)(const char *line);

/* Reads the ELF, makes an atmega2560 at 16 MHz and loads it, hands every line
 * from UART0 to on_line, turns off simavr's echo of UART0 to stdout, starts
 * the 100 us clock and adds the pin change interrupts of ports J and K that
 * simavr 1.6 lacks (PCINT9..15 on PCINT1_vect, PCINT16..23 on PCINT2_vect, as
 * the ATmega2560 datasheet has them; M2V3's encoder D15/A8 needs them).
 * Returns the board, or NULL after saying why on stderr. */
avr_t *sim_board_boot(const char *elf_path, sim_line_fn on_line);

/* Resets the CPU and restores what a reset clears: the UART flags and the
 * clock's timer. A half-received line and bytes not yet sent are dropped. */
void sim_board_reset(void);

/* simulated time since boot, us (a multiple of 100) */
uint64_t sim_now_us(void);

/* run the CPU until sim_now_us() >= t_us, or for `us` more microseconds;
 * a stopped or crashed CPU prints a FAIL line and exits 1 */
void sim_run_until_us(uint64_t t_us);
void sim_run_for_us(uint64_t us);

/* all bytes of s into UART0 at once (simavr queues them in its FIFO) */
void sim_send(const char *s);

/* n bytes (at most SIM_SEND_CAP) into UART0, 2 per 100 us tick, as slow as a
 * wire; returns once the last one is in */
void sim_send_paced(const unsigned char *bytes, size_t n);

/* The IRQ of pin `bit` of port `port` ('A'..'L'): raised by the firmware's
 * writes and by the timers' compare outputs; the harness may listen to it. */
avr_irq_t *sim_pin_irq(char port, int bit);

/* Drive an input pin from outside (an encoder channel) to level 0 or 1. The
 * level stays what the pin reads, also across the firmware's writes to the same
 * port (simavr 1.6 would otherwise let the PORT bit of a pull-up win). */
void sim_pin_set(char port, int bit, int level);

/* CRC-16/CCITT-FALSE of n bytes, bit by bit (PROTOCOL.md, "Frame") */
unsigned sim_crc16(const char *s, size_t n);

/* 1 if line is "$...*XXXX" and XXXX is the CRC of what lies between */
int sim_checksum_ok(const char *line);

#endif
