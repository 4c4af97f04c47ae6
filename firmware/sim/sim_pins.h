/* The pin table of firmware/minseg-fw/src/board/pins.def, for the harnesses:
 * one row per connector of every profile. */
#ifndef MINSEG_SIM_PINS_H
#define MINSEG_SIM_PINS_H

struct sim_pin {
  const char *name; /* the board's name for it: D44, A8, PE6 */
  const char *port; /* port letter, "L" */
  int bit;
};

struct sim_connector {
  const char *profile;
  int n; /* connector M<n> */
  struct sim_pin in1, in2, a, b;
};

#define SIM_PIN_(name, port, bit, unit) {#name, #port, bit}
#define MINSEG_CONNECTOR(P, N, IN1, IN2, A, B) \
  {#P, N, SIM_PIN_ IN1, SIM_PIN_ IN2, SIM_PIN_ A, SIM_PIN_ B},
#define MINSEG_SOURCE(P, N, TEXT)
static const struct sim_connector sim_connectors[] = {
#include "../minseg-fw/src/board/pins.def"
};
#undef MINSEG_CONNECTOR
#undef MINSEG_SOURCE
#undef SIM_PIN_

#define SIM_N_CONNECTORS ((int)(sizeof sim_connectors / sizeof sim_connectors[0]))

#endif
