/* Runs the built firmware ELF in simavr against the conformance script,
 * golden/conformance.txt: commands, hostile ones included, and the exact lines
 * the board must answer. The virtual MinSeg runs the same script
 * (tests/device/test_conformance.py), so both boards answer byte for byte
 * alike. The script's rules are written at its top.
 *
 * Host bytes go into the simulated UART 2 per 100 us, slower than simavr 1.6
 * delivers them (it times the UART without U2X: 40 us a byte), so a long line
 * reaches the firmware whole, as on a wire, and never overflows simavr's FIFO.
 * Usage: sim_conformance firmware.elf PROFILE conformance.txt
 * Booting, the UART, the clock and the checksum are in sim_board.c. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_board.h"

#define FIRMWARE_NAME "minseg-fw 3.0.0"
#define SETTLE_US 4000
#define SYNC_MAX_US 200000
#define BOOT_MAX_US 100000

/* lines from the board: samples and $BOOT counted, the rest queued */
#define QUEUE_CAP 64
static char queue[QUEUE_CAP][SIM_LINE_CAP];
static int q_head, q_len;
static long last_u;
static int have_u;
static long samples, boots;
static int failures;

static void on_line(const char *line) {
  if (strncmp(line, "$S,", 3) == 0) {
    const char *p = line;
    for (int commas = 0; *p && commas < 4; ++p)
      if (*p == ',') ++commas;
    last_u = strtol(p, NULL, 10);
    have_u = 1;
    ++samples;
  } else if (strncmp(line, "$BOOT,", 6) == 0) {
    ++boots;
  } else if (q_len < QUEUE_CAP) {
    snprintf(queue[(q_head + q_len) % QUEUE_CAP], SIM_LINE_CAP, "%s", line);
    ++q_len;
  } else {
    printf("FAIL: more than %d lines not yet expected\n", QUEUE_CAP);
    exit(1);
  }
}

static void send_bytes(const unsigned char *s, size_t n) {
  sim_send_paced(s, n);
  sim_run_for_us(SETTLE_US);
}

static void wait_boot(void) {
  long before = boots;
  uint64_t end = sim_now_us() + BOOT_MAX_US;
  while (boots == before && sim_now_us() < end) sim_run_for_us(100);
  if (boots == before) {
    printf("FAIL: no $BOOT after a reset\n");
    failures++;
  }
}

static void reset_board(void) {
  sim_board_reset();
  wait_boot();
}

/* \r \n \t \0 \\ \xHH; returns the number of bytes */
static size_t unescape(const char *s, unsigned char *out) {
  size_t n = 0;
  while (*s && n < SIM_LINE_CAP) {
    if (s[0] == '\\' && s[1]) {
      char e = s[1];
      if (e == 'x' && s[2] && s[3]) {
        char hex[3] = {s[2], s[3], 0};
        out[n++] = (unsigned char)strtol(hex, NULL, 16);
        s += 4;
        continue;
      }
      out[n++] = e == 'r' ? '\r' : e == 'n' ? '\n' : e == 't' ? '\t' : e == '0' ? '\0' : e;
      s += 2;
    } else {
      out[n++] = (unsigned char)*s++;
    }
  }
  return n;
}

/* replace every `from` in s by `to` (in place, s has SIM_LINE_CAP bytes) */
static void replace(char *s, const char *from, const char *to) {
  char out[SIM_LINE_CAP];
  size_t n = 0, lf = strlen(from), lt = strlen(to);
  for (const char *p = s; *p && n < SIM_LINE_CAP - 1;) {
    if (strncmp(p, from, lf) == 0 && n + lt < SIM_LINE_CAP - 1) {
      memcpy(out + n, to, lt);
      n += lt;
      p += lf;
    } else {
      out[n++] = *p++;
    }
  }
  out[n] = '\0';
  memcpy(s, out, n + 1);
}

static void expected_line(const char *text, const char *profile, char *want) {
  size_t len = strlen(text);
  if (len > SIM_LINE_CAP - 1) len = SIM_LINE_CAP - 1;
  memcpy(want, text, len);
  want[len] = '\0';
  replace(want, "{fw}", FIRMWARE_NAME);
  replace(want, "{board}", profile);
  size_t n = strlen(want);
  if (n > 6 && strcmp(want + n - 6, "*{crc}") == 0) {
    unsigned cs = sim_crc16(want + 1, n - 7);
    snprintf(want + n - 5, SIM_LINE_CAP - (n - 5), "%04X", cs);
  }
}

static void checkpoint(int number) {
  while (q_len > 0) {
    printf("FAIL conformance.txt:%d: not expected: %s\n", number, queue[q_head]);
    failures++;
    q_head = (q_head + 1) % QUEUE_CAP;
    q_len--;
  }
}

int main(int argc, char **argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: %s firmware.elf PROFILE conformance.txt\n", argv[0]);
    return 2;
  }
  const char *profile = argv[2];
  FILE *script = fopen(argv[3], "r");
  if (!script) {
    fprintf(stderr, "cannot read %s\n", argv[3]);
    return 2;
  }
  if (!sim_board_boot(argv[1], on_line)) return 2;
  wait_boot();

  char raw[SIM_LINE_CAP + 8];
  int number = 0, steps = 0;
  while (fgets(raw, sizeof raw, script)) {
    ++number;
    raw[strcspn(raw, "\n")] = '\0';
    if (raw[0] == '\0' || raw[0] == '#') continue;
    ++steps;
    unsigned char bytes[SIM_SEND_CAP];
    if (strncmp(raw, ">>", 2) == 0 || raw[0] == '>') {
      int newline = strncmp(raw, ">>", 2) != 0;
      const char *arg = raw + (newline ? 1 : 2);
      if (*arg == ' ') ++arg;
      checkpoint(number);
      size_t n = unescape(arg, bytes);
      if (newline) bytes[n++] = '\n';
      send_bytes(bytes, n);
    } else if (strncmp(raw, "< ", 2) == 0) {
      char want[SIM_LINE_CAP];
      expected_line(raw + 2, profile, want);
      if (q_len == 0) {
        printf("FAIL conformance.txt:%d: expected %s, got nothing\n", number, want);
        failures++;
      } else {
        if (strcmp(queue[q_head], want) != 0) {
          printf("FAIL conformance.txt:%d: expected %s, got %s\n", number, want,
                 queue[q_head]);
          failures++;
        }
        q_head = (q_head + 1) % QUEUE_CAP;
        q_len--;
      }
    } else if (strncmp(raw, "= ", 2) == 0) {
      sim_run_for_us((uint64_t)(atof(raw + 2) * 1000.0 + 0.5));
    } else if (strcmp(raw, "sync") == 0) {
      long before = samples;
      uint64_t end = sim_now_us() + SYNC_MAX_US;
      while (samples == before && sim_now_us() < end) sim_run_for_us(100);
      if (samples == before) {
        printf("FAIL conformance.txt:%d: no sample line within 200 ms\n", number);
        failures++;
      }
    } else if (strncmp(raw, "u ", 2) == 0) {
      long want = strtol(raw + 2, NULL, 10);
      if (!have_u || last_u != want) {
        printf("FAIL conformance.txt:%d: expected the last sample with u = %ld, got %ld\n",
               number, want, have_u ? last_u : 0L);
        failures++;
      }
    } else if (strcmp(raw, "reset") == 0) {
      checkpoint(number);
      reset_board();
    } else {
      printf("FAIL conformance.txt:%d: unknown directive %s\n", number, raw);
      failures++;
    }
  }
  fclose(script);
  checkpoint(number + 1);
  printf("conformance (%s): %d steps, %d failed; %ld samples in %.3f s of simulated time\n",
         profile, steps, failures, samples, (double)sim_now_us() / 1e6);
  return failures == 0 ? 0 : 1;
}
