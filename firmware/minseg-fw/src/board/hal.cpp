#include "hal.h"

#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/atomic.h>

#include "../core/controller.h"
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

// ------------------------------------------------------- the pin table
// pins.def, expanded for the profile built (profile.h). Each use below defines
// MINSEG_BODY(N, IN1, IN2, ENC_A, ENC_B) and includes the table: a connector of
// another profile expands to nothing.

#define MINSEG_CAT_(a, b) a##b
#define MINSEG_CAT(a, b) MINSEG_CAT_(a, b)
// a pin is (NAME, PORT, BIT, UNIT)
#define MINSEG_PORT_(name, port, bit, unit) port
#define MINSEG_BIT_(name, port, bit, unit) bit
#define MINSEG_UNIT_(name, port, bit, unit) unit
#define MINSEG_PORT(pin) MINSEG_PORT_ pin
#define MINSEG_BIT(pin) MINSEG_BIT_ pin
#define MINSEG_UNIT(pin) MINSEG_UNIT_ pin
#define MINSEG_PIN_LEVEL(pin) ((MINSEG_CAT(PIN, MINSEG_PORT(pin)) >> MINSEG_BIT(pin)) & 1u)

// MINSEG_ONLY_<profile> is profile.h's (made from pins.def): the body for the profile built
#define MINSEG_CONNECTOR(P, ...) MINSEG_ONLY_##P(__VA_ARGS__)
#define MINSEG_SOURCE(P, N, TEXT)

// the number of connectors of this profile
#define MINSEG_BODY(N, IN1, IN2, A, B) +1
static const uint8_t kConnectors = 0
#include "pins.def"
    ;
#undef MINSEG_BODY
static_assert(kConnectors >= 1 && kConnectors <= minseg::kMaxConnectors,
              "a profile has 1 or 2 connectors");

// -------------------------------------------------------------- encoder
// One interrupt handler per connector, on every edge of both its channels. It
// only counts: one table lookup on (old state, new state), the direction, and
// the number of pins that changed. No dynamic memory, nothing that waits.

static volatile int32_t enc_count[kConnectors];
static volatile uint32_t enc_edges[kConnectors];
static volatile uint8_t enc_state[kConnectors];
static volatile bool enc_reversed;  // DIR: count the other way
static bool motor_reversed;         // DIR: swap the bridge inputs (main loop only)

static inline void encoder_edge(uint8_t i, uint8_t s) {
  const uint8_t old = enc_state[i];
  int8_t step = minseg::kQuadStep[(old << 2) | s];
  if (enc_reversed) step = static_cast<int8_t>(-step);
  enc_count[i] += step;
  const uint8_t changed = static_cast<uint8_t>(old ^ s);
  enc_edges[i] += static_cast<uint8_t>((changed & 1u) + (changed >> 1));
  enc_state[i] = s;
}

// the vector of each interrupt a table row may name
#define MINSEG_VEC_EXTINT2 INT2_vect
#define MINSEG_VEC_EXTINT3 INT3_vect
#define MINSEG_VEC_EXTINT4 INT4_vect
#define MINSEG_VEC_EXTINT5 INT5_vect
#define MINSEG_VEC_EXTINT6 INT6_vect
#define MINSEG_VEC_EXTINT7 INT7_vect
#define MINSEG_VEC_PCINT_9 PCINT1_vect
#define MINSEG_VEC_PCINT_16 PCINT2_vect
#define MINSEG_VEC(pin) MINSEG_CAT(MINSEG_VEC_, MINSEG_UNIT(pin))

// raw levels (A << 1) | B of connector N, and its handler on both vectors
#define MINSEG_BODY(N, IN1, IN2, A, B)                                              \
  static inline uint8_t read_ab_##N() {                                             \
    return static_cast<uint8_t>((MINSEG_PIN_LEVEL(A) << 1) | MINSEG_PIN_LEVEL(B));  \
  }                                                                                 \
  ISR(MINSEG_VEC(A)) { encoder_edge(N - 1, read_ab_##N()); }                        \
  ISR(MINSEG_VEC(B), ISR_ALIASOF(MINSEG_VEC(A)));
#include "pins.def"
#undef MINSEG_BODY

// Interrupt set-up per unit: any edge for INTn, pin change for PCINTn.
#define MINSEG_EXTINT(N, REG, SHIFT)                                                  \
  static inline void irq_EXTINT##N() {                                                \
    REG = static_cast<uint8_t>((REG & ~(3u << SHIFT)) | _BV(ISC##N##0)); /* any edge */ \
    EIFR = _BV(INTF##N);                                                              \
    EIMSK |= _BV(INT##N);                                                             \
  }
MINSEG_EXTINT(2, EICRA, 4)
MINSEG_EXTINT(3, EICRA, 6)
MINSEG_EXTINT(4, EICRB, 0)
MINSEG_EXTINT(5, EICRB, 2)
MINSEG_EXTINT(6, EICRB, 4)
MINSEG_EXTINT(7, EICRB, 6)
#undef MINSEG_EXTINT
// PCINT9 is PJ0 (PCINT8 on the same vector is RXD0: left out); PCINT16 is PK0.
static inline void irq_PCINT_9() {
  PCMSK1 |= _BV(PCINT9);
  PCIFR = _BV(PCIF1);
  PCICR |= _BV(PCIE1);
}
static inline void irq_PCINT_16() {
  PCMSK2 |= _BV(PCINT16);
  PCIFR = _BV(PCIF2);
  PCICR |= _BV(PCIE2);
}

static void encoder_init() {
#define MINSEG_INPUT(pin)                                                              \
  MINSEG_CAT(DDR, MINSEG_PORT(pin)) &= static_cast<uint8_t>(~_BV(MINSEG_BIT(pin)));   \
  MINSEG_CAT(PORT, MINSEG_PORT(pin)) |= _BV(MINSEG_BIT(pin)); /* pull-up */
#define MINSEG_BODY(N, IN1, IN2, A, B) \
  MINSEG_INPUT(A)                      \
  MINSEG_INPUT(B)                      \
  enc_state[N - 1] = read_ab_##N();    \
  enc_count[N - 1] = 0;                \
  enc_edges[N - 1] = 0;                \
  MINSEG_CAT(irq_, MINSEG_UNIT(A))();  \
  MINSEG_CAT(irq_, MINSEG_UNIT(B))();
#include "pins.def"
#undef MINSEG_BODY
#undef MINSEG_INPUT
}

uint8_t hal_connectors() { return kConnectors; }

int32_t hal_encoder_count(uint8_t i) {
  int32_t c;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { c = enc_count[i]; }
  return c;
}

uint32_t hal_encoder_edges(uint8_t i) {
  uint32_t e;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { e = enc_edges[i]; }
  return e;
}

uint8_t hal_encoder_pins(uint8_t i) {
  switch (i) {
#define MINSEG_BODY(N, IN1, IN2, A, B) \
  case N - 1:                          \
    return read_ab_##N();
#include "pins.def"
#undef MINSEG_BODY
    default:
      return 0;
  }
}

void hal_encoder_zero() {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    for (uint8_t i = 0; i < kConnectors; ++i) enc_count[i] = 0;
  }
}

void hal_set_direction(bool encoder_reversed, bool motor_rev) {
  enc_reversed = encoder_reversed;
  motor_reversed = motor_rev;
}

// ------------------------------------------------------------ H-bridge
// 8-bit fast PWM, prescaler 64: 16 MHz / 64 / 256 = 977 Hz on every bridge
// input (Timer 0: mode 3; Timers 3, 4, 5: mode 5). Fast PWM rather than the
// phase-correct PWM of analogWrite on Timers 3-5 because simavr 1.6 models
// fast PWM on every timer and phase-correct PWM on none: in phase-correct
// mode it fires Timer 0's overflow every 64 cycles (250 kHz), which starved
// the Arduino-core build of M1V4 (the core's millis() interrupt is on Timer 0,
// whose OC0B drives D4). Mode 3 on Timer 0 is also what the Arduino core sets
// for millis(), so the core's interrupt keeps its 1.024 ms period. Compare
// values 0 and 255 disconnect the pin from the timer and hold it low or high,
// as analogWrite does: fast PWM at 0 would still give a one-tick spike.

// out_<unit>(v, port, mask): bridge input at compare value v. PWM for 1..254;
// 0 and 255 disconnect the timer and hold the PORT bit low or high. The PORT
// register is written only when the level changes or the pin leaves the timer,
// so a PWM pin on the same port is never disturbed by a write (simavr lets a
// PORT write override a timer-driven pin until the timer's next event; the
// chip does not).
#define MINSEG_OUT(UNIT, TCCRA, COM1, OCR)                                          \
  static inline void out_##UNIT(uint8_t v, volatile uint8_t& port, uint8_t mask) { \
    if (v == 0 || v == minseg::kPwmTop) {                                           \
      const bool was_pwm = (TCCRA & _BV(COM1)) != 0;                                \
      TCCRA &= static_cast<uint8_t>(~_BV(COM1));                                    \
      const bool high = v != 0;                                                     \
      if (was_pwm || ((port & mask) != 0) != high) {                                \
        if (high) port |= mask;                                                     \
        else port &= static_cast<uint8_t>(~mask);                                   \
      }                                                                             \
    } else {                                                                        \
      OCR = v;                                                                      \
      TCCRA |= _BV(COM1);                                                           \
    }                                                                               \
  }
#define MINSEG_OC16(T, CH)                                                    \
  static inline void init_OC##T##CH() {                                       \
    TCCR##T##A = static_cast<uint8_t>((TCCR##T##A & 0xFCu) | _BV(WGM##T##0)); \
    TCCR##T##B = _BV(WGM##T##2) | _BV(CS##T##1) | _BV(CS##T##0);              \
  }                                                                           \
  MINSEG_OUT(OC##T##CH, TCCR##T##A, COM##T##CH##1, OCR##T##CH)
MINSEG_OC16(3, A)
MINSEG_OC16(3, B)
MINSEG_OC16(4, A)
MINSEG_OC16(4, C)
MINSEG_OC16(5, A)
MINSEG_OC16(5, B)
MINSEG_OC16(5, C)
#undef MINSEG_OC16

static inline void init_OC0B() {
  TCCR0A = static_cast<uint8_t>((TCCR0A & 0xFCu) | _BV(WGM01) | _BV(WGM00));
  TCCR0B = _BV(CS01) | _BV(CS00);
}
MINSEG_OUT(OC0B, TCCR0A, COM0B1, OCR0B)
#undef MINSEG_OUT

#define MINSEG_WRITE(pin, v)                                                      \
  MINSEG_CAT(out_, MINSEG_UNIT(pin))(v, MINSEG_CAT(PORT, MINSEG_PORT(pin)), \
                                     static_cast<uint8_t>(_BV(MINSEG_BIT(pin))));

void hal_bridge(uint8_t a, uint8_t b) {
  if (motor_reversed) {
    uint8_t t = a;
    a = b;
    b = t;
  }
#define MINSEG_BODY(N, IN1, IN2, A, B) \
  MINSEG_WRITE(IN1, a)                 \
  MINSEG_WRITE(IN2, b)
#include "pins.def"
#undef MINSEG_BODY
}

static void bridge_init() {
#define MINSEG_OUTPUT(pin)                                                  \
  MINSEG_CAT(init_, MINSEG_UNIT(pin))();                                    \
  MINSEG_CAT(DDR, MINSEG_PORT(pin)) |= _BV(MINSEG_BIT(pin));
#define MINSEG_BODY(N, IN1, IN2, A, B) \
  MINSEG_OUTPUT(IN1)                   \
  MINSEG_OUTPUT(IN2)
#include "pins.def"
#undef MINSEG_BODY
#undef MINSEG_OUTPUT
  hal_bridge(minseg::kPwmTop, minseg::kPwmTop);  // brake until the first command
}

// -------------------------------------------------------------- EEPROM
// The direction (DIR) in one byte: 0xA0 | bits, so an erased EEPROM (0xFF)
// reads as FWD,FWD. The write is left to hal_poll(): it starts only once the
// EEPROM is idle (a write takes 3.4 ms), so the loop never waits for it, and
// eeprom_update_byte writes only when the byte changes.

static uint8_t* const kDirAddress = reinterpret_cast<uint8_t*>(0);
static const uint8_t kDirMagic = 0xA0;
static bool dir_pending;
static uint8_t dir_to_save;

uint8_t hal_load_direction() {
  uint8_t v = eeprom_read_byte(kDirAddress);
  return (v & 0xFCu) == kDirMagic ? static_cast<uint8_t>(v & 0x03u) : 0;
}

void hal_save_direction(uint8_t dir) {
  dir_to_save = static_cast<uint8_t>(kDirMagic | (dir & 0x03u));
  dir_pending = true;
}

void hal_poll() {
  if (dir_pending && eeprom_is_ready()) {
    dir_pending = false;
    eeprom_update_byte(kDirAddress, dir_to_save);
  }
}

void hal_init() {
  timebase_init();
  uart_init();
  bridge_init();
  encoder_init();
}
