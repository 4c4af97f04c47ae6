// Encoder decoding and H-bridge levels: pure functions shared by the AVR
// board layer and the host tests. No Arduino or AVR headers.
#ifndef MINSEG_DRIVE_H
#define MINSEG_DRIVE_H

#include <stdint.h>

namespace minseg {

// x4 quadrature decoding. state = (A << 1) | B. Index the table with
// (previous_state << 2) | new_state: +1 / -1 for one valid step, 0 for no
// change or an invalid double step (both channels changed: a missed edge).
// Forward is A leading B: 00 -> 10 -> 11 -> 01 -> 00.
static const int8_t kQuadStep[16] = {0, -1, +1, 0, +1, 0, 0, -1, -1, 0, 0, +1, 0, +1, -1, 0};

// Compare values for the two H-bridge inputs driven by 8-bit PWM (0 = pin
// always low, kPwmTop = pin always high).
static const uint8_t kPwmTop = 255;

struct BridgeLevels {
  uint8_t a;  // input 1 (positive u drives current from output 1 to 2)
  uint8_t b;  // input 2
};

// duty = |u| / V_supply, clamped to 1; the sign of u picks the direction.
// brake = true: slow decay, the off-phase and zero command are both inputs
// high (DRV8833 brake). brake = false: fast decay, off-phase and zero command
// are both inputs low (DRV8833 coast).
BridgeLevels bridge_levels(int32_t u_mV, uint16_t vsupply_mV, bool brake);

// duty as a compare value 0..kPwmTop, rounded to nearest.
uint8_t duty_counts(int32_t u_mV, uint16_t vsupply_mV);

}  // namespace minseg

#endif
