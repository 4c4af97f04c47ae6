// Board profiles, chosen at build time: -DMINSEG_PROFILE_MINSEGMEGA (the
// default), -DMINSEG_PROFILE_M2V3 or -DMINSEG_PROFILE_M1V4
// (make PROFILE=MinSegMega|M2V3|M1V4). Pin maps and their sources:
// firmware/README.md.
//
// Every profile drives the two H-bridge inputs of motor 1 with 8-bit
// phase-correct PWM at 490 Hz (the Arduino analogWrite frequency, which the
// Simulink-generated code used) and counts the encoder of motor 1 on every
// edge of both channels.
#ifndef MINSEG_PROFILE_H
#define MINSEG_PROFILE_H

#if !defined(MINSEG_PROFILE_MINSEGMEGA) && !defined(MINSEG_PROFILE_M2V3) && \
    !defined(MINSEG_PROFILE_M1V4)
#define MINSEG_PROFILE_MINSEGMEGA
#endif

#if defined(MINSEG_PROFILE_MINSEGMEGA)
// DRV8833. IN1 = D44 (PL5, OC5C), IN2 = D45 (PL4, OC5B), Timer 5.
// Encoder A = PE6 (INT6), B = PE7 (INT7): not Arduino pins; external
// interrupts on any edge.
#define MINSEG_BOARD_NAME "MinSegMega"
#define MINSEG_ENC_EXTINT_67
#define MINSEG_PWM_TIMER5_C_B
#elif defined(MINSEG_PROFILE_M2V3)
// SN754410. 1A = D6 (PH3, OC4A), 2A = D8 (PH5, OC4C), Timer 4.
// Encoder A = D15 (PJ0, PCINT9), B = A8 = D62 (PK0, PCINT16): pin-change
// interrupts.
#define MINSEG_BOARD_NAME "M2V3"
#define MINSEG_ENC_PCINT_J0_K0
#define MINSEG_PWM_TIMER4_A_C
#elif defined(MINSEG_PROFILE_M1V4)
// SN754410. 1A = D5 (PE3, OC3A, Timer 3), 2A = D4 (PG5, OC0B, Timer 0).
// Encoder A = D2 (PE4, INT4), B = D3 (PE5, INT5): external interrupts.
#define MINSEG_BOARD_NAME "M1V4"
#define MINSEG_ENC_EXTINT_45
#define MINSEG_PWM_TIMER3A_TIMER0B
#endif

#if defined(MINSEG_PROFILE_MINSEGMEGA) + defined(MINSEG_PROFILE_M2V3) + \
        defined(MINSEG_PROFILE_M1V4) != 1
#error "define exactly one MINSEG_PROFILE_*"
#endif

#endif
