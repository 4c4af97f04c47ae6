#include "hal.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/atomic.h>

#include "../core/drive.h"
#include "profile.h"

#if F_CPU != 16000000UL
#error "timings below assume a 16 MHz clock"
#endif

// ------------------------------------------------------------- time base
// Timer 1, normal mode, prescaler 8: one tick = 0.5 us, overflow every
// 32768 us. The overflow interrupt adds 32768 to a 32-bit microsecond base.

static volatile uint32_t us_base;

ISR(TIMER1_OVF_vect) { us_base += 32768u; }

uint32_t hal_micros() {
  uint32_t base;
  uint16_t t;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    base = us_base;
    t = TCNT1;
    // an overflow that happened after interrupts were disabled
    if ((TIFR1 & _BV(TOV1)) && t < 0x8000u) base += 32768u;
  }
  return base + (t >> 1);
}

static void timebase_init() {
  TCCR1A = 0;
  TCCR1B = _BV(CS11);
  TCCR1C = 0;
  TCNT1 = 0;
  TIFR1 = _BV(TOV1);
  TIMSK1 = _BV(TOIE1);
}

// ---------------------------------------------------------------- UART0
// 500000 baud, 8N1: U2X with UBRR = 3 is exact at 16 MHz.

static const uint16_t kRxSize = 128;  // powers of two: indices wrap with a mask
static const uint16_t kTxSize = 256;
static volatile uint8_t rx_buf[kRxSize];
static volatile uint8_t rx_head, rx_tail;
static volatile uint8_t tx_buf[kTxSize];
static volatile uint8_t tx_head, tx_tail;

ISR(USART0_RX_vect) {
  uint8_t c = UDR0;
  uint8_t next = static_cast<uint8_t>((rx_head + 1u) & (kRxSize - 1u));
  if (next != rx_tail) {  // when full the byte is lost: the line assembler
    rx_buf[rx_head] = c;  // then sees a malformed line and answers $ERR
    rx_head = next;
  }
}

ISR(USART0_UDRE_vect) {
  if (tx_head == tx_tail) {
    UCSR0B &= static_cast<uint8_t>(~_BV(UDRIE0));
    return;
  }
  UDR0 = tx_buf[tx_tail];
  tx_tail = static_cast<uint8_t>(tx_tail + 1u);  // 256 entries: wraps by itself
}

static void uart_init() {
  UCSR0A = _BV(U2X0);
  UBRR0 = 3;
  UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
  UCSR0B = _BV(RXCIE0) | _BV(RXEN0) | _BV(TXEN0);
}

int16_t hal_uart_getc() {
  if (rx_head == rx_tail) return -1;
  uint8_t c = rx_buf[rx_tail];
  rx_tail = static_cast<uint8_t>((rx_tail + 1u) & (kRxSize - 1u));
  return c;
}

uint8_t hal_uart_tx_free() {
  return static_cast<uint8_t>(kTxSize - 1u - static_cast<uint8_t>(tx_head - tx_tail));
}

void hal_uart_write(const char* s, uint8_t n) {
  for (uint8_t i = 0; i < n; ++i) {
    uint8_t next = static_cast<uint8_t>(tx_head + 1u);
    while (next == tx_tail) {
      // buffer full: wait for the UDRE interrupt to make room
    }
    tx_buf[tx_head] = static_cast<uint8_t>(s[i]);
    tx_head = next;
    UCSR0B |= _BV(UDRIE0);
  }
}

// -------------------------------------------------------------- encoder
// The interrupt only counts: one table lookup on (old state, new state).

static volatile int32_t enc_count;
static volatile uint8_t enc_state;

#if defined(MINSEG_ENC_EXTINT_67)
static inline uint8_t read_ab() {
  uint8_t p = PINE;
  return static_cast<uint8_t>((((p >> PE6) & 1u) << 1) | ((p >> PE7) & 1u));
}
#elif defined(MINSEG_ENC_EXTINT_45)
static inline uint8_t read_ab() {
  uint8_t p = PINE;
  return static_cast<uint8_t>((((p >> PE4) & 1u) << 1) | ((p >> PE5) & 1u));
}
#elif defined(MINSEG_ENC_PCINT_J0_K0)
static inline uint8_t read_ab() {
  return static_cast<uint8_t>((((PINJ >> PJ0) & 1u) << 1) | ((PINK >> PK0) & 1u));
}
#endif

static inline uint8_t read_state() {
  uint8_t s = read_ab();
#if defined(MINSEG_ENCODER_REVERSED)
  s = static_cast<uint8_t>(((s & 1u) << 1) | (s >> 1));  // swap A and B
#endif
  return s;
}

static inline void encoder_edge() {
  uint8_t s = read_state();
  enc_count += minseg::kQuadStep[(enc_state << 2) | s];
  enc_state = s;
}

#if defined(MINSEG_ENC_EXTINT_67)
ISR(INT6_vect) { encoder_edge(); }
ISR(INT7_vect, ISR_ALIASOF(INT6_vect));
#elif defined(MINSEG_ENC_EXTINT_45)
ISR(INT4_vect) { encoder_edge(); }
ISR(INT5_vect, ISR_ALIASOF(INT4_vect));
#elif defined(MINSEG_ENC_PCINT_J0_K0)
ISR(PCINT1_vect) { encoder_edge(); }
ISR(PCINT2_vect, ISR_ALIASOF(PCINT1_vect));
#endif

static void encoder_init() {
#if defined(MINSEG_ENC_EXTINT_67)
  DDRE &= static_cast<uint8_t>(~(_BV(PE6) | _BV(PE7)));
  PORTE |= _BV(PE6) | _BV(PE7);  // pull-ups
  EICRB = static_cast<uint8_t>((EICRB & 0x0F) | _BV(ISC60) | _BV(ISC70));  // any edge
  EIFR = _BV(INTF6) | _BV(INTF7);
  EIMSK |= _BV(INT6) | _BV(INT7);
#elif defined(MINSEG_ENC_EXTINT_45)
  DDRE &= static_cast<uint8_t>(~(_BV(PE4) | _BV(PE5)));
  PORTE |= _BV(PE4) | _BV(PE5);  // pull-ups
  EICRB = static_cast<uint8_t>((EICRB & 0xF0) | _BV(ISC40) | _BV(ISC50));  // any edge
  EIFR = _BV(INTF4) | _BV(INTF5);
  EIMSK |= _BV(INT4) | _BV(INT5);
#elif defined(MINSEG_ENC_PCINT_J0_K0)
  DDRJ &= static_cast<uint8_t>(~_BV(PJ0));
  PORTJ |= _BV(PJ0);  // pull-ups
  DDRK &= static_cast<uint8_t>(~_BV(PK0));
  PORTK |= _BV(PK0);
  PCMSK1 = _BV(PCINT9);   // PJ0 only (PCINT8 is RXD0)
  PCMSK2 = _BV(PCINT16);  // PK0 only
  PCIFR = _BV(PCIF1) | _BV(PCIF2);
  PCICR |= _BV(PCIE1) | _BV(PCIE2);
#endif
  enc_state = read_state();
  enc_count = 0;
}

int32_t hal_encoder_count() {
  int32_t c;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { c = enc_count; }
  return c;
}

void hal_encoder_zero() {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { enc_count = 0; }
}

// ------------------------------------------------------------ H-bridge
// 8-bit phase-correct PWM, prescaler 64: 16 MHz / 64 / 510 = 490 Hz.
// Compare value 0 keeps the pin low, 255 (TOP) keeps it high.

static void bridge_init() {
#if defined(MINSEG_PWM_TIMER5_C_B)
  OCR5C = 255;  // brake until the first command
  OCR5B = 255;
  TCCR5A = _BV(COM5B1) | _BV(COM5C1) | _BV(WGM50);
  TCCR5B = _BV(CS51) | _BV(CS50);
  DDRL |= _BV(PL5) | _BV(PL4);
#elif defined(MINSEG_PWM_TIMER4_A_C)
  OCR4A = 255;
  OCR4C = 255;
  TCCR4A = _BV(COM4A1) | _BV(COM4C1) | _BV(WGM40);
  TCCR4B = _BV(CS41) | _BV(CS40);
  DDRH |= _BV(PH3) | _BV(PH5);
#elif defined(MINSEG_PWM_TIMER3A_TIMER0B)
  OCR3A = 255;
  TCCR3A = _BV(COM3A1) | _BV(WGM30);
  TCCR3B = _BV(CS31) | _BV(CS30);
  DDRE |= _BV(PE3);
  OCR0B = 255;
  TCCR0A = _BV(COM0B1) | _BV(WGM00);
  TCCR0B = _BV(CS01) | _BV(CS00);
  DDRG |= _BV(PG5);
#endif
}

void hal_bridge(uint8_t a, uint8_t b) {
#if defined(MINSEG_MOTOR_REVERSED)
  uint8_t t = a;
  a = b;
  b = t;
#endif
#if defined(MINSEG_PWM_TIMER5_C_B)
  OCR5C = a;
  OCR5B = b;
#elif defined(MINSEG_PWM_TIMER4_A_C)
  OCR4A = a;
  OCR4C = b;
#elif defined(MINSEG_PWM_TIMER3A_TIMER0B)
  OCR3A = a;
  OCR0B = b;
#endif
}

void hal_init() {
  timebase_init();
  uart_init();
  bridge_init();
  encoder_init();
}
