/* Firmware in the loop: the built ELF in simavr with a DC motor and its encoder
 * on one connector of the profile (pins from pins.def), the other connector
 * open. Only this proves a pin map; the conformance script proves the protocol.
 *
 * The motor: every 4 us (the PWM timers' tick at prescaler 64) the harness reads
 * the levels the firmware puts on the connector's two bridge inputs (the pins'
 * IRQs, raised by the timers' compare outputs and by PORT writes) and applies
 * u_A = V_s (IN1 - IN2) to the first-order model T dw/dt + w = K u_A (equal
 * levels: the terminals shorted, u_A = 0, as in the BRAKE off-phase). The
 * model's angle sets the encoder pins in quadrature, 720 counts per wheel
 * revolution (x4): A leads B for a positive angle.
 *
 * Checked, for the connector given:
 *   - Task 4: V = 2.5, 3.5, 4.5 V: the speed from the firmware's counts has the
 *     sign of u and |omega_ss| is within 2 % of the model's K u (V_s = SUP);
 *   - the other connector's bridge gets the same mean voltage (driven alike);
 *   - counts per wheel revolution: the firmware's count over the model's turns;
 *   - DIR,REV,FWD and DIR,FWD,REV flip the sign, DIR,FWD,FWD restores it;
 *   - Task 10: STEP,0,4500,1000,2: omega at the end of each high half within 2 %
 *     of K 4.5 V, at rest at the end of each low half, and the mean speed over
 *     the first 200 ms after each rising edge within 3 % of the model's;
 *   - DIAG names this connector as the one in use, the open one with 0 edges.
 * Prints ok/FAIL lines and one "figures" line for benchmarks/firmware_in_loop.py.
 * Usage: sim_fil firmware.elf PROFILE CONNECTOR (1 or 2)
 *        sim_fil --connectors PROFILE   (prints the profile's connector numbers) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_board.h"
#include "sim_pins.h"

/* the motor model: NXT-like, "angular velocities up to 7 rad/s or so" at 4.5 V */
#define MODEL_K 1.6       /* rad/s per V */
#define MODEL_T 0.08      /* s */
#define MODEL_VS 5.0      /* V, the bridge supply; the firmware's SUP default is 5000 mV */
#define TICK_CYCLES 64    /* 4 us at 16 MHz */
#define TICK_S 4e-6
#define COUNTS_PER_REV 720
#define TWO_PI 6.283185307179586

static int failures;
static void expect(int ok, const char *what) {
  printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) failures++;
}

/* ------------------------------------------------------------ the board's lines */
#define MAX_SAMPLES 4096
struct sample {
  double t; /* s, board time */
  long count, u;
};
static struct sample samples[MAX_SAMPLES];
static int n_samples;
static uint32_t t_first_us;
static int have_first;
static char last_diag[SIM_LINE_CAP], last_reply[SIM_LINE_CAP];

static void on_line(const char *line) {
  unsigned long seq, t;
  long count, u;
  if (sscanf(line, "$S,%lu,%lu,%ld,%ld*", &seq, &t, &count, &u) == 4 && sim_checksum_ok(line)) {
    if (!have_first) {
      t_first_us = (uint32_t)t;
      have_first = 1;
    }
    if (n_samples < MAX_SAMPLES) {
      samples[n_samples].t = (double)(uint32_t)((uint32_t)t - t_first_us) / 1e6;
      samples[n_samples].count = count;
      samples[n_samples].u = u;
      n_samples++;
    }
  } else if (strncmp(line, "$DIAG,", 6) == 0) {
    snprintf(last_diag, sizeof last_diag, "%s", line);
  } else if (strncmp(line, "$OK,", 4) == 0 || strncmp(line, "$ERR,", 5) == 0) {
    snprintf(last_reply, sizeof last_reply, "%s", line);
  }
}

/* ------------------------------------------------------------ pins and motor */
static const struct sim_connector *conn[2];
static int n_conn, motor; /* motor: index into conn of the connector with the motor */
static int level[2][2];   /* [connector][IN1, IN2] as the firmware drives them now */
static double bridge_sum[2];
static long bridge_ticks;

static double omega, theta, theta0; /* rad/s, rad, rad at the start (model) */
static long enc_index;      /* floor(theta / (2 pi / 720)) */

static void on_level(avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  *(int *)param = (int)(value & 1u);
}

static void set_encoder(long index) {
  static const int a[4] = {0, 1, 1, 0}; /* 00 -> 10 -> 11 -> 01: A leads B */
  static const int b[4] = {0, 0, 1, 1};
  int q = (int)(((index % 4) + 4) % 4);
  sim_pin_set(conn[motor]->a.port[0], conn[motor]->a.bit, a[q]);
  sim_pin_set(conn[motor]->b.port[0], conn[motor]->b.bit, b[q]);
}

static avr_cycle_count_t motor_tick(avr_t *avr, avr_cycle_count_t when, void *param) {
  (void)avr;
  (void)param;
  for (int c = 0; c < n_conn; ++c) bridge_sum[c] += MODEL_VS * (level[c][0] - level[c][1]);
  bridge_ticks++;
  double u_a = MODEL_VS * (level[motor][0] - level[motor][1]);
  omega += TICK_S / MODEL_T * (MODEL_K * u_a - omega);
  theta += omega * TICK_S;
  long index = (long)floor(theta / (TWO_PI / COUNTS_PER_REV));
  while (index != enc_index) { /* one quadrature step at a time */
    enc_index += index > enc_index ? 1 : -1;
    set_encoder(enc_index);
  }
  return when + TICK_CYCLES;
}

/* ------------------------------------------------------------ helpers */
static double now_s(void) { return (double)sim_now_us() / 1e6; }

static void command(const char *text) {
  char line[64];
  snprintf(line, sizeof line, "%s\n", text);
  last_reply[0] = '\0';
  sim_send(line);
  sim_run_for_us(5000);
}

/* let board time pass with a PING every 250 ms (the watchdog wants one a second) */
static void hold(double seconds) {
  double end = now_s() + seconds;
  while (now_s() + 0.25 < end) {
    sim_run_for_us(250000);
    sim_send("PING\n");
  }
  sim_run_until_us((uint64_t)(end * 1e6 + 0.5));
}

/* the mean speed from the firmware's counts between board times t0 and t1 (s),
 * both on sample instants: the samples nearest to them (a sample's t_us lies a
 * few us after its instant) */
static double speed_between(double t0, double t1) {
  int i0 = -1, i1 = -1;
  for (int i = 0; i < n_samples; ++i) {
    if (i0 < 0 && samples[i].t >= t0 - 0.0125) i0 = i;
    if (samples[i].t <= t1 + 0.0125) i1 = i;
  }
  if (i0 < 0 || i1 <= i0) return NAN;
  return (double)(samples[i1].count - samples[i0].count) * TWO_PI / COUNTS_PER_REV /
         (samples[i1].t - samples[i0].t);
}

/* board time of the latest sample (s) */
static double board_now(void) { return n_samples ? samples[n_samples - 1].t : 0.0; }

/* hold V for 1.1 s (about 14 T), then the speed over the next 0.5 s */
static double steady_speed(long u_mV, double *bridge_this, double *bridge_other) {
  char cmd[32];
  snprintf(cmd, sizeof cmd, "V,%ld", u_mV);
  command(cmd);
  hold(1.1);
  double t0 = board_now();
  for (int c = 0; c < 2; ++c) bridge_sum[c] = 0;
  bridge_ticks = 0;
  hold(0.5);
  double t1 = board_now();
  *bridge_this = bridge_sum[motor] / (double)bridge_ticks;
  *bridge_other = n_conn > 1 ? bridge_sum[1 - motor] / (double)bridge_ticks : *bridge_this;
  return speed_between(t0, t1);
}

int main(int argc, char **argv) {
  setvbuf(stdout, NULL, _IOLBF, 0);
  if (argc == 3 && strcmp(argv[1], "--connectors") == 0) {
    int found = 0;
    for (int i = 0; i < SIM_N_CONNECTORS; ++i)
      if (strcmp(sim_connectors[i].profile, argv[2]) == 0)
        printf("%s%d", found++ ? " " : "", sim_connectors[i].n);
    printf("\n");
    return found ? 0 : 2;
  }
  if (argc != 4) {
    fprintf(stderr, "usage: %s firmware.elf PROFILE CONNECTOR\n", argv[0]);
    return 2;
  }
  const char *profile = argv[2];
  int wanted = atoi(argv[3]);
  for (int i = 0; i < SIM_N_CONNECTORS && n_conn < 2; ++i)
    if (strcmp(sim_connectors[i].profile, profile) == 0) conn[n_conn++] = &sim_connectors[i];
  motor = -1;
  for (int c = 0; c < n_conn; ++c)
    if (conn[c]->n == wanted) motor = c;
  if (n_conn == 0 || motor < 0) {
    fprintf(stderr, "no connector M%s in profile %s\n", argv[3], profile);
    return 2;
  }
  printf("%s, motor on M%d: IN1 %s, IN2 %s, encoder A %s, B %s; %s\n", profile,
         conn[motor]->n, conn[motor]->in1.name, conn[motor]->in2.name, conn[motor]->a.name,
         conn[motor]->b.name, n_conn > 1 ? "the other connector open" : "one connector");

  avr_t *avr = sim_board_boot(argv[1], on_line);
  if (!avr) return 2;
  for (int c = 0; c < n_conn; ++c) {
    avr_irq_register_notify(sim_pin_irq(conn[c]->in1.port[0], conn[c]->in1.bit), on_level,
                            &level[c][0]);
    avr_irq_register_notify(sim_pin_irq(conn[c]->in2.port[0], conn[c]->in2.bit), on_level,
                            &level[c][1]);
  }
  /* The encoder rests at 11, what the pull-ups read, mid-way in count 2: its
   * pins are first driven at the first edge. */
  enc_index = 2;
  theta = theta0 = 2.5 * TWO_PI / COUNTS_PER_REV;
  avr_cycle_timer_register(avr, TICK_CYCLES, motor_tick, NULL);
  sim_run_for_us(100000);

  /* ---- Task 4 */
  const long task4[3] = {2500, 3500, 4500};
  double worst_err = 0.0;
  int signs_ok = 1, alike_ok = 1;
  char what[640];
  for (int k = 0; k < 3; ++k) {
    double b_this, b_other;
    double w = steady_speed(task4[k], &b_this, &b_other);
    double w_model = MODEL_K * (double)task4[k] / 1000.0;
    double err = (fabs(w) - w_model) / w_model * 100.0;
    if (fabs(err) > fabs(worst_err)) worst_err = err;
    signs_ok = signs_ok && w > 0;
    alike_ok = alike_ok && fabs(b_this - b_other) < 0.01 * MODEL_VS;
    snprintf(what, sizeof what,
             "V,%ld: omega_ss %.3f rad/s, model %.3f (%+.2f %%), bridge M%d %.3f V, other %.3f V",
             task4[k], w, w_model, err, conn[motor]->n, b_this, b_other);
    expect(w > 0 && fabs(err) <= 2.0 && fabs(b_this - b_other) < 0.01 * MODEL_VS, what);
  }
  command("STOP");
  hold(1.0); /* at rest: about 12 T */
  double revs = (theta - theta0) / TWO_PI;
  long count_end = n_samples ? samples[n_samples - 1].count : 0;
  double cpr = revs != 0.0 ? (double)count_end / revs : 0.0;
  snprintf(what, sizeof what, "counts per wheel revolution %.2f (count %ld over %.3f turns)", cpr,
           count_end, revs);
  expect(fabs(cpr - COUNTS_PER_REV) < 1.0, what);
  command("DIAG");
  char want_diag[96];
  snprintf(want_diag, sizeof want_diag, "$DIAG,%s,M%d,", n_conn > 1 ? "M1+M2" : "M1",
           conn[motor]->n);
  int diag_ok = strncmp(last_diag, want_diag, strlen(want_diag)) == 0;
  if (n_conn > 1) {
    char open_mid[16], open_end[16];
    snprintf(open_mid, sizeof open_mid, ",M%d:11:0,", conn[1 - motor]->n);
    snprintf(open_end, sizeof open_end, ",M%d:11:0*", conn[1 - motor]->n);
    diag_ok = diag_ok && (strstr(last_diag, open_mid) || strstr(last_diag, open_end));
  }
  snprintf(what, sizeof what, "DIAG names M%d in use%s: %s", conn[motor]->n,
           n_conn > 1 ? ", the open one idle with 0 edges" : "", last_diag);
  expect(diag_ok, what);

  /* ---- DIR: each REV flips the sign of the speed for the same u */
  const char *dirs[3] = {"DIR,REV,FWD", "DIR,FWD,REV", "DIR,FWD,FWD"};
  const int sign_want[3] = {-1, -1, +1};
  int dir_ok = 1;
  for (int k = 0; k < 3; ++k) {
    command(dirs[k]);
    double b_this, b_other;
    double w = steady_speed(3000, &b_this, &b_other);
    double w_model = MODEL_K * 3.0;
    int ok = (w > 0 ? 1 : -1) == sign_want[k] && fabs(fabs(w) - w_model) < 0.02 * w_model;
    dir_ok = dir_ok && ok;
    snprintf(what, sizeof what, "%s, V,3000: omega_ss %.3f rad/s (sign %s expected)", dirs[k], w,
             sign_want[k] > 0 ? "+" : "-");
    expect(ok, what);
  }
  command("STOP");
  hold(1.0);

  /* ---- Task 10: a step sequence, board-timed */
  int first = n_samples;
  command("STEP,0,4500,1000,2");
  hold(4.2);
  /* the edges, from the samples' u (in force from that sample on) */
  double rises[2] = {NAN, NAN};
  int n_rises = 0;
  for (int i = first > 0 ? first : 1; i < n_samples && n_rises < 2; ++i)
    if (samples[i].u == 4500 && samples[i - 1].u == 0) rises[n_rises++] = samples[i].t;
  expect(n_rises == 2, "STEP,0,4500,1000,2: two rising edges in the samples' u");
  double w_ss = MODEL_K * 4.5, worst_step = 0.0, worst_rise = 0.0;
  int step_ok = 1;
  for (int p = 0; p < 2; ++p) {
    double rise = rises[p], fall = rise + 1.0, end = fall + 1.0;
    double w_high = speed_between(fall - 0.2, fall);
    double w_low = speed_between(end - 0.2, end);
    double w_rise = speed_between(rise, rise + 0.2);
    double rise_model = w_ss * (1.0 - MODEL_T / 0.2 * (1.0 - exp(-0.2 / MODEL_T)));
    double e_high = (w_high - w_ss) / w_ss * 100.0;
    double e_rise = (w_rise - rise_model) / w_ss * 100.0;
    if (fabs(e_high) > fabs(worst_step)) worst_step = e_high;
    if (fabs(e_rise) > fabs(worst_rise)) worst_rise = e_rise;
    int ok = fabs(e_high) <= 2.0 && fabs(w_low) < 0.01 * w_ss && fabs(e_rise) <= 3.0;
    step_ok = step_ok && ok;
    snprintf(what, sizeof what,
             "step %d: end of high %.3f rad/s (%+.2f %% of %.3f), end of low %.3f, first 200 ms "
             "%.3f (model %.3f, %+.2f %%)",
             p + 1, w_high, e_high, w_ss, w_low, w_rise, rise_model, e_rise);
    expect(ok, what);
  }

  printf("figures %s M%d sign=%s omega_err_pct=%+.2f counts_per_rev=%.2f dir_rev=%s "
         "step_err_pct=%+.2f rise_err_pct=%+.2f alike=%s\n",
         profile, conn[motor]->n, signs_ok ? "ok" : "WRONG", worst_err, cpr,
         dir_ok ? "ok" : "WRONG", worst_step, worst_rise, alike_ok ? "ok" : "WRONG");
  printf("%d checks failed; %.1f s of simulated time\n", failures, now_s());
  return failures == 0 ? 0 : 1;
}
