// The firmware's entry points, shared by the bare avr-libc build (main.cpp)
// and the Arduino IDE sketch (minseg-fw.ino).
#ifndef MINSEG_APP_H
#define MINSEG_APP_H

void minseg_setup();
void minseg_loop();  // non-blocking: serves received bytes, the watchdog and the schedule

#endif
