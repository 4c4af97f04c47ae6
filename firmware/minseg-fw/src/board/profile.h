// The board profile, chosen at build time: make PROFILE=<name> defines
// MINSEG_PROFILE_<NAME> (the name in upper case). In the Arduino IDE, define one
// here to build another profile than the default, e.g. #define MINSEG_PROFILE_M2V3.
// The profiles are those of pins.def (the one table of pins, with their sources;
// firmware/README.md shows it); profiles.h, made from it, checks that exactly one
// is chosen and names it (MINSEG_BOARD_NAME).
//
// Every profile drives the two H-bridge inputs of every connector alike with
// 8-bit fast PWM at 977 Hz and counts every connector's encoder on every edge
// of both channels (hal.cpp).
#ifndef MINSEG_PROFILE_H
#define MINSEG_PROFILE_H

#include "profiles.h"

#endif
