/* Runs the built firmware ELF in simavr (libsimavr) and checks, over the
 * simulated UART0, that it:
 *   1. prints exactly the $BOOT line,
 *   2. answers ID with a valid $ID line for the expected profile,
 *   3. accepts V,2500 ($OK,V,2500) and streams samples 25 ms apart (board
 *      time, t_us) carrying u = 2500 and consecutive seq,
 *   4. counts quadrature edges driven on each connector's encoder pins (x4,
 *      pins from pins.def), follows the first connector that counted, and
 *      tells it all in $DIAG,
 *   5. stops the motor by itself after more than 1 s of host silence ($EV,WDOG,
 *      then samples with u = 0),
 *   6. keeps up at the shortest period, 2 ms: no gaps in seq, t_us 2 ms apart.
 * Usage: sim_handshake firmware.elf PROFILE
 * Booting, the UART, the clock and the checksum are in sim_board.c. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "sim_board.h"
#include "sim_pins.h"

#define MAX_LINES 1024
static char lines[MAX_LINES][96];
static uint64_t line_time_us[MAX_LINES];
static int n_lines;
static int failures;

static void on_line(const char *line) {
  if (n_lines < MAX_LINES) {
    snprintf(lines[n_lines], sizeof lines[n_lines], "%s", line);
    line_time_us[n_lines] = sim_now_us();
    n_lines++;
  }
}

static void expect(int ok, const char *what) {
  printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) failures++;
}

/* index of the first line at or after `from` that starts with prefix, or -1 */
static int find_line(int from, const char *prefix) {
  for (int i = from; i < n_lines; ++i)
    if (strncmp(lines[i], prefix, strlen(prefix)) == 0) return i;
  return -1;
}

struct sample {
  unsigned long seq, t;
  long count, u;
};

static int parse_sample(const char *line, struct sample *s) {
  return sim_checksum_ok(line) &&
         sscanf(line, "$S,%lu,%lu,%ld,%ld*", &s->seq, &s->t, &s->count, &s->u) == 4;
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s firmware.elf PROFILE\n", argv[0]);
    return 2;
  }
  const char *profile = argv[2];
  const struct sim_connector *conn[2];
  int n_conn = 0;
  for (int i = 0; i < SIM_N_CONNECTORS && n_conn < 2; ++i)
    if (strcmp(sim_connectors[i].profile, profile) == 0) conn[n_conn++] = &sim_connectors[i];
  if (n_conn == 0) {
    fprintf(stderr, "unknown profile %s\n", profile);
    return 2;
  }

  avr_t *avr = sim_board_boot(argv[1], on_line);
  if (!avr) return 2;

  /* 1. boot line */
  sim_run_until_us(5000);
  expect(n_lines >= 1 && strcmp(lines[0], "$BOOT,minseg-fw 3.0.0,3*A813") == 0,
         "boot line $BOOT,minseg-fw 3.0.0,3*A813");

  /* 2. ID */
  for (int c = 0; c < n_conn; ++c) { /* encoders idle high (pull-ups) */
    sim_pin_set(conn[c]->a.port[0], conn[c]->a.bit, 1);
    sim_pin_set(conn[c]->b.port[0], conn[c]->b.bit, 1);
  }
  int before = n_lines;
  sim_send("ID\n");
  sim_run_for_us(5000);
  char want_id[96];
  snprintf(want_id, sizeof want_id, "$ID,minseg-fw 3.0.0,3,%s,720,25000,5000,BRAKE,FWD,FWD*",
           profile);
  int id = find_line(before, "$ID,");
  expect(id >= 0 && strncmp(lines[id], want_id, strlen(want_id)) == 0 &&
             sim_checksum_ok(lines[id]),
         "reply to ID names firmware, protocol 3, the profile and FWD,FWD");
  if (id >= 0) printf("      %s\n", lines[id]);

  /* 3. V and the sample stream */
  before = n_lines;
  sim_send("$V,2500*ACE8\n");
  sim_run_for_us(5000);
  expect(find_line(before, "$OK,V,2500*61E5") >= 0, "V,2500 -> $OK,V,2500*61E5");
  sim_run_for_us(100000);
  struct sample s[8];
  int ns = 0;
  for (int i = before; i < n_lines && ns < 8; ++i)
    if (parse_sample(lines[i], &s[ns])) ns++;
  int stream_ok = ns >= 3;
  for (int i = 1; i < ns; ++i) {
    long dt = (long)(s[i].t - s[i - 1].t);
    stream_ok = stream_ok && s[i].seq == s[i - 1].seq + 1 && dt >= 24900 && dt <= 25100;
  }
  expect(stream_ok, "samples: consecutive seq, t_us 25000 +- 100 apart");
  expect(ns >= 1 && s[ns - 1].u == 2500, "samples carry u = 2500 after V,2500");

  /* 4. encoders: two forward cycles = 8 edges (A leads B), 1 ms apart, on each
   * connector in turn; the count follows M1, the first to count */
  /* forward order in (A,B): 00 -> 10 -> 11 -> 01 -> 00; from 11: 01, 00, 10, 11 */
  const int fa[4] = {0, 0, 1, 1};
  const int fb[4] = {1, 0, 0, 1};
  uint64_t silent_from = 0;
  for (int c = 0; c < n_conn; ++c) {
    for (int k = 0; k < 8; ++k) {
      sim_pin_set(conn[c]->a.port[0], conn[c]->a.bit, fa[k % 4]);
      sim_pin_set(conn[c]->b.port[0], conn[c]->b.bit, fb[k % 4]);
      sim_run_for_us(1000);
    }
    silent_from = sim_now_us(); /* the last command */
    before = n_lines;
    sim_send("DIAG\n");
    sim_run_for_us(60000);
    ns = 0;
    for (int i = before; i < n_lines && ns < 8; ++i)
      if (parse_sample(lines[i], &s[ns])) ns++;
    char what[160];
    snprintf(what, sizeof what,
             "8 forward edges on M%d's encoder (%s, %s): the sample count is +8 (x4, M1's)",
             conn[c]->n, conn[c]->a.name, conn[c]->b.name);
    expect(ns >= 1 && s[ns - 1].count == 8, what);
    if (ns >= 1) printf("      count: %ld\n", s[ns - 1].count);
    int dg = find_line(before, "$DIAG,");
    char want[96];
    snprintf(want, sizeof want, "%s,M1,", n_conn == 2 ? "$DIAG,M1+M2" : "$DIAG,M1");
    for (int d = 0; d < n_conn; ++d)
      snprintf(want + strlen(want), sizeof want - strlen(want), "%sM%d:11:%d", d ? "," : "", d + 1,
               d <= c ? 8 : 0);
    snprintf(what, sizeof what, "DIAG after M%d's edges: %s", conn[c]->n, want);
    expect(dg >= 0 && sim_checksum_ok(lines[dg]) && strncmp(lines[dg], want, strlen(want)) == 0 &&
               lines[dg][strlen(want)] == '*',
           what);
    if (dg >= 0) printf("      %s\n", lines[dg]);
  }

  /* 5. watchdog: silence for more than 1 s */
  before = n_lines;
  sim_run_for_us(1200000);
  int wd = find_line(before, "$EV,WDOG*EBC5");
  expect(wd >= 0, "host silent: $EV,WDOG*EBC5");
  if (wd >= 0) {
    double after_ms = (double)(line_time_us[wd] - silent_from) / 1000.0;
    printf("      WDOG %.1f ms after the last command\n", after_ms);
    expect(after_ms > 1000.0 && after_ms < 1010.0, "WDOG after 1000 ms, within 10 ms");
    struct sample t;
    int found = 0;
    for (int i = wd + 1; i < n_lines; ++i)
      if (parse_sample(lines[i], &t)) {
        found = 1;
        break;
      }
    expect(found && t.u == 0, "samples after WDOG carry u = 0");
  }

  /* 6. the fastest sample period: 2 ms, 500 samples/s through the UART */
  sim_send("P,2000\n");
  sim_run_for_us(5000);
  int ok_p = find_line(before, "$OK,P,2000*");
  expect(ok_p >= 0, "P,2000 -> $OK,P,2000");
  int first = n_lines;
  sim_run_for_us(200000);
  struct sample prev, cur_s;
  int n_fast = 0, fast_ok = 1;
  long dt_min = 1000000, dt_max = 0;
  for (int i = first; i < n_lines; ++i) {
    if (!parse_sample(lines[i], &cur_s)) continue;
    if (n_fast > 0) {
      long dt = (long)(cur_s.t - prev.t);
      if (dt < dt_min) dt_min = dt;
      if (dt > dt_max) dt_max = dt;
      fast_ok = fast_ok && cur_s.seq == prev.seq + 1;
    }
    prev = cur_s;
    n_fast++;
  }
  printf("      %d samples in 200 ms, spacing %ld..%ld us\n", n_fast, dt_min, dt_max);
  expect(fast_ok && n_fast >= 95 && dt_min >= 1900 && dt_max <= 2100,
         "2 ms period: no seq gap, t_us 2000 +- 100 apart");

  printf("%d checks failed; %d lines received in %.3f s of simulated time\n", failures, n_lines,
         (double)sim_now_us() / 1e6);
  return failures == 0 ? 0 : 1;
}
