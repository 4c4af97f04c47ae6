// Board profiles, chosen at build time: -DMINSEG_PROFILE_MINSEGMEGA (the
// default), -DMINSEG_PROFILE_M2V3 or -DMINSEG_PROFILE_M1V4
// (make PROFILE=MinSegMega|M2V3|M1V4). The pins of each profile, with their
// sources, are in pins.def (the one table; firmware/README.md shows it).
//
// Every profile drives the two H-bridge inputs of every connector alike with
// 8-bit fast PWM at 977 Hz and counts every connector's encoder on every edge
// of both channels (hal.cpp).
#ifndef MINSEG_PROFILE_H
#define MINSEG_PROFILE_H

#if !defined(MINSEG_PROFILE_MINSEGMEGA) && !defined(MINSEG_PROFILE_M2V3) && \
    !defined(MINSEG_PROFILE_M1V4)
#define MINSEG_PROFILE_MINSEGMEGA
#endif

#if defined(MINSEG_PROFILE_MINSEGMEGA)
#define MINSEG_BOARD_NAME "MinSegMega"  // DRV8833, connectors M1 (right) and M2 (left)
#elif defined(MINSEG_PROFILE_M2V3)
#define MINSEG_BOARD_NAME "M2V3"  // SN754410, connectors M1 and M2
#elif defined(MINSEG_PROFILE_M1V4)
#define MINSEG_BOARD_NAME "M1V4"  // SN754410, connector M1
#endif

#if defined(MINSEG_PROFILE_MINSEGMEGA) + defined(MINSEG_PROFILE_M2V3) + \
        defined(MINSEG_PROFILE_M1V4) != 1
#error "define exactly one MINSEG_PROFILE_*"
#endif

#endif
