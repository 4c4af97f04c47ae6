#include "controller.h"

namespace minseg {

const char kFirmware[] = "minseg-fw 3.0.0";

int32_t clamp_i32(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : (v > hi ? hi : v); }

uint32_t clamp_period_us(int32_t requested_us) {
  int32_t p = clamp_i32(requested_us, static_cast<int32_t>(kPeriodMinUs),
                        static_cast<int32_t>(kPeriodMaxUs));
  return static_cast<uint32_t>((p + 500) / 1000) * 1000u;
}

// ------------------------------------------------------------- StepSequencer

void StepSequencer::start(int32_t low_mV, int32_t high_mV, uint32_t half_samples, uint16_t n) {
  low_ = low_mV;
  high_ = high_mV;
  half_ = half_samples == 0 ? 1 : half_samples;
  n_ = n;
  pos_ = 0;
  active_ = n > 0;
}

void StepSequencer::clamp_levels(int32_t limit_mV) {
  low_ = clamp_i32(low_, -limit_mV, limit_mV);
  high_ = clamp_i32(high_, -limit_mV, limit_mV);
}

int32_t StepSequencer::next(uint16_t* edge, bool* done) {
  *edge = 0;
  *done = false;
  uint32_t phase = pos_ / half_;  // 0: first high half, 1: first low half, ...
  if (phase >= 2u * n_) {
    active_ = false;
    *done = true;
    return low_;
  }
  if (pos_ % half_ == 0 && phase % 2u == 0) *edge = static_cast<uint16_t>(phase / 2u + 1u);
  ++pos_;
  return phase % 2u == 0 ? high_ : low_;
}

// ---------------------------------------------------------------- Controller

Controller::Controller(Board* board, const char* board_name)
    : board_(board),
      board_name_(board_name),
      period_(kPeriodDefaultUs),
      vsup_(kSupplyDefaultMv),
      brake_(true),
      stream_(true),
      u_(0),
      pending_(false),
      pending_u_(0),
      step_pending_(false),
      step_half_samples_(1),
      next_due_(0),
      seq_(0),
      last_valid_(0),
      dir_(0),
      active_(kNoConnector) {
  step_args_[0] = step_args_[1] = step_args_[2] = 0;
}

void Controller::begin(uint32_t now_us) {
  dir_ = static_cast<uint8_t>(board_->load_direction() & (kDirEncoderRev | kDirMotorRev));
  board_->set_direction(dir_);
  board_->drive(0, vsup_, brake_);
  LineWriter w("BOOT");
  w.str(kFirmware).u32(kProtoVersion);
  const char* s = w.finish();
  board_->send(s, w.len(), false);
  next_due_ = now_us + period_;
  last_valid_ = now_us;
}

void Controller::feed(char c, uint32_t now_us) {
  LineAssembler::Status st = rx_.feed(c);
  if (st == LineAssembler::kLine) handle_line(rx_.line(), rx_.len(), now_us);
  else if (st == LineAssembler::kOverlong) send_err(kErrArgs, "");
}

bool Controller::running() const {
  return u_ != 0 || step_.active() || step_pending_ || (pending_ && pending_u_ != 0);
}

void Controller::stop_motor() {
  step_.abort();
  step_pending_ = false;
  pending_ = false;
  u_ = 0;
  board_->drive(0, vsup_, brake_);
}

void Controller::send_ok(const char* name) {
  LineWriter w("OK");
  w.str(name);
  const char* s = w.finish();
  board_->send(s, w.len(), false);
}

void Controller::send_err(Err e, const char* detail) {
  LineWriter w("ERR");
  w.str(err_name(e));
  if (detail[0] != '\0') w.str(detail);
  const char* s = w.finish();
  board_->send(s, w.len(), false);
}

void Controller::send_id() {
  LineWriter w("ID");
  w.str(kFirmware).u32(kProtoVersion).str(board_name_).u32(kCountsPerRev).u32(period_).u32(vsup_);
  w.str(brake_ ? "BRAKE" : "COAST");
  w.str((dir_ & kDirEncoderRev) ? "REV" : "FWD").str((dir_ & kDirMotorRev) ? "REV" : "FWD");
  const char* s = w.finish();
  board_->send(s, w.len(), false);
}

// $DIAG,<drive>,<active>,<conn>:<AB>:<edges>...: every connector is driven.
void Controller::send_diag() {
  find_active();
  const uint8_t n = board_->connectors();
  char drive[3 * kMaxConnectors];
  uint8_t k = 0;
  for (uint8_t i = 0; i < n && i < kMaxConnectors; ++i) {
    if (i > 0) drive[k++] = '+';
    drive[k++] = 'M';
    drive[k++] = static_cast<char>('1' + i);
  }
  drive[k] = '\0';
  char active[5] = {'N', 'O', 'N', 'E', '\0'};
  if (active_ != kNoConnector) {
    active[0] = 'M';
    active[1] = static_cast<char>('1' + active_);
    active[2] = '\0';
  }
  LineWriter w("DIAG");
  w.str(drive).str(active);
  for (uint8_t i = 0; i < n && i < kMaxConnectors; ++i) {
    // one field: M<i>:<A><B>:<edges>
    const uint8_t ab = board_->encoder_pins(i);
    char f[18] = {'M', static_cast<char>('1' + i), ':', static_cast<char>('0' + ((ab >> 1) & 1u)),
                  static_cast<char>('0' + (ab & 1u)), ':'};
    uint8_t e = format_u32(board_->encoder_edges(i), f + 6);
    f[6 + e] = '\0';
    w.str(f);
  }
  const char* s = w.finish();
  board_->send(s, w.len(), false);
}

// The first connector whose encoder counted kActiveEdges edges since reset
// becomes the active one, for good (until the next reset).
void Controller::find_active() {
  if (active_ != kNoConnector) return;
  const uint8_t n = board_->connectors();
  for (uint8_t i = 0; i < n && i < kMaxConnectors; ++i) {
    if (board_->encoder_edges(i) >= kActiveEdges) {
      active_ = static_cast<int8_t>(i);
      return;
    }
  }
}

int32_t Controller::count() {
  find_active();
  return active_ == kNoConnector ? 0 : board_->encoder_count(static_cast<uint8_t>(active_));
}

void Controller::handle_line(const char* s, uint8_t n, uint32_t now_us) {
  Command c;
  char detail[12];
  Err e = parse_command(s, n, &c, detail);
  if (e == kIgnore) return;
  if (e == kOk && (c.id == kStep || c.id == kDir) && step_active()) {
    e = kErrBusy;
    detail[0] = '\0';
  }
  if (e != kOk) {
    // Checksum and busy errors carry no detail; the others name the command.
    if (e == kErrChecksum || e == kErrBusy) detail[0] = '\0';
    send_err(e, detail);
    return;  // nothing changes, not even the watchdog
  }
  last_valid_ = now_us;
  execute(c, now_us);
}

void Controller::execute(const Command& c, uint32_t now_us) {
  (void)now_us;
  const int32_t lim = static_cast<int32_t>(vsup_);
  switch (c.id) {
    case kId:
      send_id();
      break;
    case kPing:
      send_ok("PING");
      break;
    case kV: {
      int32_t u = clamp_i32(c.arg[0], -lim, lim);
      step_.abort();
      step_pending_ = false;
      pending_ = true;  // in force from the next sample instant
      pending_u_ = u;
      LineWriter w("OK");
      const char* s = w.str("V").i32(u).finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kStep: {
      int32_t low = clamp_i32(c.arg[0], -lim, lim);
      int32_t high = clamp_i32(c.arg[1], -lim, lim);
      int32_t half_ms = clamp_i32(c.arg[2], kHalfMinMs, kHalfMaxMs);
      int32_t n = clamp_i32(c.arg[3], kStepsMin, kStepsMax);
      // Edges fall on sample instants: the half period becomes a whole
      // number of sample periods (nearest, at least one).
      uint32_t half_samples = (static_cast<uint32_t>(half_ms) * 1000u + period_ / 2u) / period_;
      if (half_samples == 0) half_samples = 1;
      uint32_t applied_half_ms = half_samples * (period_ / 1000u);
      pending_ = false;
      step_pending_ = true;
      step_args_[0] = low;
      step_args_[1] = high;
      step_args_[2] = n;
      step_half_samples_ = half_samples;
      LineWriter w("OK");
      const char* s = w.str("STEP").i32(low).i32(high).u32(applied_half_ms).i32(n).finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kStop:
      stop_motor();
      send_ok("STOP");
      break;
    case kP: {
      uint32_t p = clamp_period_us(c.arg[0]);
      if (step_active()) stop_motor();  // P aborts a step sequence
      next_due_ = next_due_ - period_ + p;  // the last sample instant + the new period
      period_ = p;
      LineWriter w("OK");
      const char* s = w.str("P").u32(p).finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kZ:
      board_->encoder_zero();
      send_ok("Z");
      break;
    case kSup: {
      vsup_ = static_cast<uint16_t>(clamp_i32(c.arg[0], kSupplyMinMv, kSupplyMaxMv));
      const int32_t nl = static_cast<int32_t>(vsup_);
      u_ = clamp_i32(u_, -nl, nl);
      pending_u_ = clamp_i32(pending_u_, -nl, nl);
      step_args_[0] = clamp_i32(step_args_[0], -nl, nl);
      step_args_[1] = clamp_i32(step_args_[1], -nl, nl);
      step_.clamp_levels(nl);
      board_->drive(u_, vsup_, brake_);
      LineWriter w("OK");
      const char* s = w.str("SUP").u32(vsup_).finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kZm: {
      brake_ = c.arg[0] != 0;
      board_->drive(u_, vsup_, brake_);
      LineWriter w("OK");
      const char* s = w.str("ZM").str(brake_ ? "BRAKE" : "COAST").finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kDir: {
      dir_ = static_cast<uint8_t>((c.arg[0] != 0 ? kDirEncoderRev : 0) |
                                  (c.arg[1] != 0 ? kDirMotorRev : 0));
      board_->set_direction(dir_);
      board_->save_direction(dir_);
      board_->drive(u_, vsup_, brake_);  // the new polarity at once
      LineWriter w("OK");
      const char* s = w.str("DIR")
                          .str((dir_ & kDirEncoderRev) ? "REV" : "FWD")
                          .str((dir_ & kDirMotorRev) ? "REV" : "FWD")
                          .finish();
      board_->send(s, w.len(), false);
      break;
    }
    case kDiag:
      send_diag();
      break;
    case kStream: {
      stream_ = c.arg[0] != 0;
      LineWriter w("OK");
      const char* s = w.str("STREAM").u32(stream_ ? 1u : 0u).finish();
      board_->send(s, w.len(), false);
      break;
    }
    default:
      break;
  }
}

void Controller::poll(uint32_t now_us) {
  find_active();
  if (running() && static_cast<uint32_t>(now_us - last_valid_) > kWatchdogUs) {
    stop_motor();
    LineWriter w("EV");
    const char* s = w.str("WDOG").finish();
    board_->send(s, w.len(), false);
  }
  if (static_cast<int32_t>(now_us - next_due_) >= 0) sample(now_us);
}

void Controller::sample(uint32_t now_us) {
  // The command in force from this sample on.
  uint16_t edge = 0;
  bool done = false;
  if (step_pending_) {
    step_pending_ = false;
    step_.start(step_args_[0], step_args_[1], step_half_samples_,
                static_cast<uint16_t>(step_args_[2]));
  }
  if (step_.active()) {
    u_ = step_.next(&edge, &done);
  } else if (pending_) {
    pending_ = false;
    u_ = pending_u_;
  }
  board_->drive(u_, vsup_, brake_);
  int32_t n = count();

  if (stream_) {
    LineWriter w("S");
    const char* s = w.u32(seq_).u32(now_us).i32(n).i32(u_).finish();
    board_->send(s, w.len(), true);  // a dropped sample shows as a gap in seq
    ++seq_;
  }
  if (edge != 0) {
    LineWriter w("EV");
    const char* s = w.str("STEP").u32(edge).u32(step_args_[2]).finish();
    board_->send(s, w.len(), false);
  }
  if (done) {
    LineWriter w("EV");
    const char* s = w.str("STEPDONE").finish();
    board_->send(s, w.len(), false);
  }

  // Next instant on the fixed grid; instants the loop missed are skipped
  // (and counted in seq when streaming, so the host sees the gap).
  next_due_ += period_;
  if (static_cast<int32_t>(now_us - next_due_) >= 0) {
    uint32_t missed = (now_us - next_due_) / period_ + 1u;
    next_due_ += missed * period_;
    if (stream_) seq_ += missed;
  }
}

}  // namespace minseg
