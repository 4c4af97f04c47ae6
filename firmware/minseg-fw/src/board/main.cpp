// Entry point of the bare avr-libc build (make -C firmware). The Arduino IDE
// build uses minseg-fw.ino instead and defines ARDUINO.
#ifndef ARDUINO
#include "app.h"

int main() {
  minseg_setup();
  for (;;) minseg_loop();
}
#endif
