// ATmega2560 hardware layer on bare avr-libc (no Arduino core): time base,
// UART0 with ring buffers, encoder interrupts, H-bridge PWM and the
// direction kept in EEPROM. The pins come from pins.def.
#ifndef MINSEG_HAL_H
#define MINSEG_HAL_H

#include <stdint.h>

void hal_init();                 // call with interrupts disabled
uint32_t hal_micros();           // Timer 1, 0.5 us resolution, wraps after 71.6 min
int16_t hal_uart_getc();         // next received byte, or -1
uint8_t hal_uart_tx_free();      // bytes free in the transmit buffer
void hal_uart_write(const char* s, uint8_t n);  // waits while the buffer is full
// Connectors 0..hal_connectors()-1 of the profile's pin table (pins.def).
uint8_t hal_connectors();
int32_t hal_encoder_count(uint8_t i);
uint32_t hal_encoder_edges(uint8_t i);  // every edge since reset
uint8_t hal_encoder_pins(uint8_t i);    // raw levels now, (A << 1) | B
void hal_encoder_zero();                // every connector's count
void hal_set_direction(bool encoder_reversed, bool motor_reversed);
// Compare values for bridge input 1 and 2 of every connector, 0 = low, 255 = high.
void hal_bridge(uint8_t a, uint8_t b);
uint8_t hal_load_direction();           // from EEPROM, minseg::kDir* bits
void hal_save_direction(uint8_t dir);   // to EEPROM (by hal_poll), only when it changed
void hal_poll();                        // main loop: starts a pending EEPROM write

#endif
