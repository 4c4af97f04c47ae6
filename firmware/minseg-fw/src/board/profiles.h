// Made by tools/pins_table.py from pins.def (--write); do not edit: make host-test
// fails while it differs. The board profiles of pins.def, chosen at build time (or in
// profile.h, which includes this file): one of
// -DMINSEG_PROFILE_MINSEGMEGA, -DMINSEG_PROFILE_M2V3, -DMINSEG_PROFILE_M1V4
// (make PROFILE=MinSegMega|M2V3|M1V4); without one, MinSegMega, the first of the table.
#ifndef MINSEG_PROFILES_H
#define MINSEG_PROFILES_H

#if !defined(MINSEG_PROFILE_MINSEGMEGA) && !defined(MINSEG_PROFILE_M2V3) && !defined(MINSEG_PROFILE_M1V4)
#define MINSEG_PROFILE_MINSEGMEGA
#endif

#if defined(MINSEG_PROFILE_MINSEGMEGA) + defined(MINSEG_PROFILE_M2V3) + defined(MINSEG_PROFILE_M1V4) != 1
#error "define exactly one MINSEG_PROFILE_*"
#endif

// MINSEG_ONLY_<profile>(...): the connectors of pins.def of the profile built expand to
// MINSEG_BODY(...) (hal.cpp defines it at each use), those of the others to nothing.
#if defined(MINSEG_PROFILE_MINSEGMEGA)
#define MINSEG_BOARD_NAME "MinSegMega"
#define MINSEG_ONLY_MinSegMega(...) MINSEG_BODY(__VA_ARGS__)
#else
#define MINSEG_ONLY_MinSegMega(...)
#endif
#if defined(MINSEG_PROFILE_M2V3)
#define MINSEG_BOARD_NAME "M2V3"
#define MINSEG_ONLY_M2V3(...) MINSEG_BODY(__VA_ARGS__)
#else
#define MINSEG_ONLY_M2V3(...)
#endif
#if defined(MINSEG_PROFILE_M1V4)
#define MINSEG_BOARD_NAME "M1V4"
#define MINSEG_ONLY_M1V4(...) MINSEG_BODY(__VA_ARGS__)
#else
#define MINSEG_ONLY_M1V4(...)
#endif

#endif
