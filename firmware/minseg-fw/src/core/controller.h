// The board's behaviour under protocol 2, independent of the hardware:
// command handling with clamping, the sample schedule, the board-timed step
// sequencer and the host-silence watchdog. No Arduino or AVR headers, no
// dynamic memory. The AVR build and the host tests drive it through Board.
#ifndef MINSEG_CONTROLLER_H
#define MINSEG_CONTROLLER_H

#include <stdint.h>

#include "protocol.h"

namespace minseg {

extern const char kFirmware[];            // "minseg-fw 2.0.0"
static const uint16_t kCountsPerRev = 720;  // x4 decoding, per wheel revolution

// Limits and defaults (PROTOCOL.md, "Host to board").
static const uint32_t kWatchdogUs = 1000000;  // stop after more than 1000 ms of silence
static const uint32_t kPeriodDefaultUs = 25000;
static const uint32_t kPeriodMinUs = 2000;
static const uint32_t kPeriodMaxUs = 100000;
static const uint16_t kSupplyDefaultMv = 5000;
static const uint16_t kSupplyMinMv = 3000;
static const uint16_t kSupplyMaxMv = 12000;
static const int32_t kHalfMinMs = 20;
static const int32_t kHalfMaxMs = 60000;
static const int32_t kStepsMin = 1;
static const int32_t kStepsMax = 1000;

int32_t clamp_i32(int32_t v, int32_t lo, int32_t hi);
// P argument -> applied period: clamped to 2000..100000 us, rounded to the
// nearest multiple of 1000 us (half up).
uint32_t clamp_period_us(int32_t requested_us);

// What the controller needs from the hardware.
class Board {
 public:
  virtual int32_t encoder_count() = 0;
  virtual void encoder_zero() = 0;
  // Apply a motor command now (duty = |u| / V_supply, see drive.h).
  virtual void drive(int32_t u_mV, uint16_t vsupply_mV, bool brake) = 0;
  // Queue a line for the host. A droppable line (a sample) may be dropped
  // when the transmit buffer is full: then it returns false.
  virtual bool send(const char* s, uint8_t n, bool droppable) = 0;

 protected:
  ~Board() {}
};

// Board-timed square wave: high for half_samples sample periods, low for
// half_samples, n times. Every level change happens at a sample instant.
class StepSequencer {
 public:
  StepSequencer() : active_(false), low_(0), high_(0), half_(1), n_(0), pos_(0) {}
  void start(int32_t low_mV, int32_t high_mV, uint32_t half_samples, uint16_t n);
  void abort() { active_ = false; }
  bool active() const { return active_; }
  void clamp_levels(int32_t limit_mV);
  // Called at each sample instant while active: returns the command in force
  // from this sample on. *edge = k (1..n) when period k starts at this
  // sample, else 0. *done = true when the sequence ended here (u = low).
  int32_t next(uint16_t* edge, bool* done);

 private:
  bool active_;
  int32_t low_, high_;
  uint32_t half_;
  uint16_t n_;
  uint32_t pos_;  // samples since the start
};

class Controller {
 public:
  Controller(Board* board, const char* board_name);

  void begin(uint32_t now_us);                 // prints $BOOT, starts the schedule
  void feed(char c, uint32_t now_us);          // one received byte
  void handle_line(const char* s, uint8_t n, uint32_t now_us);
  void poll(uint32_t now_us);                  // watchdog and sample schedule

  // State, for the host tests.
  int32_t u_mV() const { return u_; }
  uint32_t period_us() const { return period_; }
  uint16_t vsupply_mV() const { return vsup_; }
  bool brake() const { return brake_; }
  bool streaming() const { return stream_; }
  bool step_active() const { return step_.active() || step_pending_; }
  uint32_t next_sample_us() const { return next_due_; }
  uint32_t seq() const { return seq_; }

 private:
  bool running() const;
  void stop_motor();
  void send_ok(const char* name);
  void send_err(Err e, const char* detail);
  void send_id();
  void execute(const Command& c, uint32_t now_us);
  void sample(uint32_t now_us);

  Board* board_;
  const char* board_name_;
  LineAssembler rx_;
  uint32_t period_;
  uint16_t vsup_;
  bool brake_;
  bool stream_;
  int32_t u_;            // command in force
  bool pending_;         // a V command waiting for the next sample instant
  int32_t pending_u_;
  StepSequencer step_;
  bool step_pending_;    // STEP accepted, starts at the next sample instant
  int32_t step_args_[3];
  uint32_t step_half_samples_;
  uint32_t next_due_;    // next sample instant (micros)
  uint32_t seq_;
  uint32_t last_valid_;  // time of the last valid command (micros)
};

}  // namespace minseg

#endif
