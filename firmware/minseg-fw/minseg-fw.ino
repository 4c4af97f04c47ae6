// MinSeg firmware, protocol 3 (see firmware/PROTOCOL.md and firmware/README.md).
// The real work is in src/: src/core (board-independent, host-tested) and
// src/board (ATmega2560 registers; it does not use the Arduino core's
// Serial, millis or analogWrite). Choose the board profile in
// src/board/profile.h (default MinSegMega, the first of src/board/pins.def) or
// build with `make -C firmware PROFILE=...`.
#include "src/board/app.h"

void setup() { minseg_setup(); }

void loop() { minseg_loop(); }
