// ATmega2560 hardware layer on bare avr-libc (no Arduino core): time base,
// UART0 with ring buffers, encoder interrupts and H-bridge PWM.
#ifndef MINSEG_HAL_H
#define MINSEG_HAL_H

#include <stdint.h>

void hal_init();                 // call with interrupts disabled
uint32_t hal_micros();           // Timer 1, 0.5 us resolution, wraps after 71.6 min
int16_t hal_uart_getc();         // next received byte, or -1
uint8_t hal_uart_tx_free();      // bytes free in the transmit buffer
void hal_uart_write(const char* s, uint8_t n);  // waits while the buffer is full
int32_t hal_encoder_count();
void hal_encoder_zero();
void hal_bridge(uint8_t a, uint8_t b);  // compare values, 255 = input always high

#endif
