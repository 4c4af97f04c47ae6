// The board's behaviour under protocol 3, independent of the hardware:
// command handling with clamping, the sample schedule, the board-timed step
// sequencer, the host-silence watchdog, the run-time direction (DIR) and the
// choice of the connector whose count the samples carry. No Arduino or AVR headers, no
// dynamic memory. The AVR build and the host tests drive it through Board.
#ifndef MINSEG_CONTROLLER_H
#define MINSEG_CONTROLLER_H

#include <stdint.h>

#include "protocol.h"

namespace minseg {

extern const char kFirmware[];            // "minseg-fw 3.0.0"
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
static const uint8_t kMaxConnectors = 2;
// A connector becomes the active one (the samples' count follows it) once its
// encoder counted this many edges since reset (PROTOCOL.md).
static const uint32_t kActiveEdges = 4;
static const int8_t kNoConnector = -1;

// Direction bits as kept in EEPROM and passed to Board::set_direction.
static const uint8_t kDirEncoderRev = 1;
static const uint8_t kDirMotorRev = 2;

int32_t clamp_i32(int32_t v, int32_t lo, int32_t hi);
// P argument -> applied period: clamped to 2000..100000 us, rounded to the
// nearest multiple of 1000 us (half up).
uint32_t clamp_period_us(int32_t requested_us);

// What the controller needs from the hardware. Connectors are numbered
// 0..connectors()-1 and named M1, M2, ... in $DIAG.
class Board {
 public:
  virtual uint8_t connectors() = 0;  // 1..kMaxConnectors
  // Connector i's encoder: its count (x4, already in the direction set by
  // set_direction), every edge it saw since reset whatever its direction, and
  // the raw levels of its pins now, (A << 1) | B.
  virtual int32_t encoder_count(uint8_t i) = 0;
  virtual uint32_t encoder_edges(uint8_t i) = 0;
  virtual uint8_t encoder_pins(uint8_t i) = 0;
  virtual void encoder_zero() = 0;  // every connector's count (not the edges)
  // Apply a motor command now to every connector (duty = |u| / V_supply, see
  // drive.h), in the polarity set by set_direction.
  virtual void drive(int32_t u_mV, uint16_t vsupply_mV, bool brake) = 0;
  // kDirEncoderRev: count the other way from now on (the count itself kept);
  // kDirMotorRev: swap the bridge inputs (takes effect at the next drive()).
  virtual void set_direction(uint8_t dir) = 0;
  // The direction kept over resets (EEPROM): load at begin(), save on DIR (the
  // board writes only when it changed).
  virtual uint8_t load_direction() = 0;
  virtual void save_direction(uint8_t dir) = 0;
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
  uint8_t direction() const { return dir_; }
  int8_t active_connector() const { return active_; }

 private:
  bool running() const;
  void stop_motor();
  void send_ok(const char* name);
  void send_err(Err e, const char* detail);
  void send_id();
  void send_diag();
  void find_active();
  int32_t count();
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
  uint8_t dir_;          // kDirEncoderRev | kDirMotorRev
  int8_t active_;        // connector the count follows, kNoConnector until one has 4 edges
};

}  // namespace minseg

#endif
