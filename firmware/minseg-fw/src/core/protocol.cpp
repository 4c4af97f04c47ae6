#include "protocol.h"

namespace minseg {

uint16_t crc16_update(uint16_t crc, uint8_t byte) {
  // One byte of CRC-16 with polynomial 0x1021, MSB first, without a table: the
  // polynomial's three terms applied to the byte's top nibble and the whole byte.
  crc = static_cast<uint16_t>((crc >> 8) | (crc << 8));
  crc ^= byte;
  crc ^= static_cast<uint16_t>((crc & 0xFFu) >> 4);
  crc ^= static_cast<uint16_t>(crc << 12);
  crc ^= static_cast<uint16_t>((crc & 0xFFu) << 5);
  return crc;
}

uint16_t checksum(const char* s, uint8_t n) {
  uint16_t crc = 0xFFFFu;
  for (uint8_t i = 0; i < n; ++i) crc = crc16_update(crc, static_cast<uint8_t>(s[i]));
  return crc;
}

uint8_t format_u32(uint32_t v, char* out) {
  // Repeated subtraction of powers of ten: no 32-bit division, which costs
  // hundreds of cycles per digit on the AVR.
  static const uint32_t kPow10[10] = {1000000000u, 100000000u, 10000000u, 1000000u, 100000u,
                                      10000u,      1000u,      100u,      10u,      1u};
  uint8_t n = 0;
  for (uint8_t i = 0; i < 10; ++i) {
    char d = '0';
    while (v >= kPow10[i]) {
      v -= kPow10[i];
      ++d;
    }
    if (d != '0' || n > 0 || i == 9) out[n++] = d;
  }
  return n;
}

uint8_t format_i32(int32_t v, char* out) {
  if (v < 0) {
    out[0] = '-';
    // -(v + 1) + 1 avoids overflow at INT32_MIN
    return static_cast<uint8_t>(1 + format_u32(static_cast<uint32_t>(-(v + 1)) + 1u, out + 1));
  }
  return format_u32(static_cast<uint32_t>(v), out);
}

// ---------------------------------------------------------------- LineWriter

LineWriter::LineWriter(const char* name) : n_(0) {
  put('$');
  str(name);
}

void LineWriter::put(char c) {
  if (n_ < kCap) buf_[n_++] = c;
}

LineWriter& LineWriter::str(const char* s) {
  if (n_ > 1) put(',');
  while (*s) put(*s++);
  return *this;
}

LineWriter& LineWriter::u32(uint32_t v) {
  char tmp[10];
  uint8_t k = format_u32(v, tmp);
  put(',');
  for (uint8_t i = 0; i < k; ++i) put(tmp[i]);
  return *this;
}

LineWriter& LineWriter::i32(int32_t v) {
  char tmp[11];
  uint8_t k = format_i32(v, tmp);
  put(',');
  for (uint8_t i = 0; i < k; ++i) put(tmp[i]);
  return *this;
}

const char* LineWriter::finish() {
  static const char kHex[] = "0123456789ABCDEF";
  uint16_t cs = checksum(buf_ + 1, static_cast<uint8_t>(n_ - 1));
  put('*');
  for (int8_t shift = 12; shift >= 0; shift -= 4) put(kHex[(cs >> shift) & 0x0F]);
  put('\n');
  return buf_;
}

// ------------------------------------------------------------- LineAssembler

LineAssembler::Status LineAssembler::feed(char c) {
  if (ready_) {  // the previous call returned kLine: start a new line
    ready_ = false;
    n_ = 0;
  }
  if (c == '\n') {
    bool was_long = overlong_;
    overlong_ = false;
    if (was_long) {
      n_ = 0;
      return kOverlong;
    }
    if (n_ > 0 && buf_[n_ - 1] == '\r') --n_;
    if (n_ > kMaxLine) {
      n_ = 0;
      return kOverlong;
    }
    buf_[n_] = '\0';
    ready_ = true;
    return kLine;
  }
  if (overlong_) return kNone;
  if (n_ >= kMaxLine + 1) {  // room for kMaxLine bytes plus a trailing '\r'
    overlong_ = true;
    n_ = 0;
    return kNone;
  }
  buf_[n_++] = c;
  return kNone;
}

// -------------------------------------------------------------------- parser

namespace {

enum ArgKind { kNoArgs, kInts, kMode, kBit, kDirs };

struct CmdSpec {
  const char* name;
  uint8_t nargs;
  uint8_t kind;
};

// The host commands of protocol 3, indexed by CmdId.
const CmdSpec kCmds[kCmdCount] = {
    {"ID", 0, kNoArgs},   {"PING", 0, kNoArgs}, {"V", 1, kInts},   {"STEP", 4, kInts},
    {"STOP", 0, kNoArgs}, {"P", 1, kInts},      {"Z", 0, kNoArgs}, {"SUP", 1, kInts},
    {"ZM", 1, kMode},     {"STREAM", 1, kBit},  {"DIR", 2, kDirs},  {"DIAG", 0, kNoArgs},
};

bool field_equals(const char* f, uint8_t n, const char* lit) {
  uint8_t i = 0;
  for (; i < n; ++i)
    if (lit[i] == '\0' || lit[i] != f[i]) return false;
  return lit[i] == '\0';
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// Decimal integer, optional '-', no '+', no spaces. Returns kOk, kErrArgs
// (not a number) or kErrRange (outside int32).
Err parse_int(const char* f, uint8_t n, int32_t* out) {
  uint8_t i = 0;
  bool neg = false;
  if (n > 0 && f[0] == '-') {
    neg = true;
    i = 1;
  }
  if (i >= n) return kErrArgs;
  uint32_t limit = neg ? 2147483648u : 2147483647u;
  uint32_t v = 0;
  bool too_big = false;
  for (; i < n; ++i) {
    if (f[i] < '0' || f[i] > '9') return kErrArgs;
    uint32_t d = static_cast<uint32_t>(f[i] - '0');
    if (too_big || v > (limit - d) / 10u) {
      too_big = true;  // keep checking the remaining characters are digits
      continue;
    }
    v = v * 10u + d;
  }
  if (too_big) return kErrRange;
  *out = neg ? static_cast<int32_t>(0u - v) : static_cast<int32_t>(v);
  return kOk;
}

}  // namespace

const char* err_name(Err e) {
  switch (e) {
    case kErrChecksum: return "CHECKSUM";
    case kErrUnknown: return "UNKNOWN";
    case kErrArgs: return "ARGS";
    case kErrRange: return "RANGE";
    case kErrBusy: return "BUSY";
    default: return "";
  }
}

const char* cmd_name(CmdId c) { return kCmds[c].name; }

Err parse_command(const char* line, uint8_t len, Command* cmd, char* detail) {
  detail[0] = '\0';
  if (len == 0) return kIgnore;
  const char* s = line;
  uint8_t n = len;
  if (s[0] == '$') {
    ++s;
    --n;
  }
  // A '$' anywhere but at the start: two lines run together. Malformed.
  for (uint8_t i = 0; i < n; ++i)
    if (s[i] == '$') return kErrArgs;
  // Optional checksum: '*' followed by exactly four hex digits (either case), then the end.
  for (uint8_t i = 0; i < n; ++i) {
    if (s[i] != '*') continue;
    if (n - i != 1 + kChecksumDigits) return kErrChecksum;
    uint16_t want = 0;
    for (uint8_t k = 1; k <= kChecksumDigits; ++k) {
      int d = hex_value(s[i + k]);
      if (d < 0) return kErrChecksum;
      want = static_cast<uint16_t>((want << 4) | static_cast<uint16_t>(d));
    }
    if (checksum(s, i) != want) return kErrChecksum;
    n = i;
    break;
  }
  // Name: upper-case letters up to the first ',' or the end.
  uint8_t name_len = 0;
  while (name_len < n && s[name_len] != ',') ++name_len;
  bool name_ok = name_len > 0 && name_len <= 11;
  for (uint8_t i = 0; i < name_len && name_ok; ++i) name_ok = s[i] >= 'A' && s[i] <= 'Z';
  if (!name_ok) return kErrUnknown;
  int found = -1;
  for (uint8_t c = 0; c < kCmdCount; ++c)
    if (field_equals(s, name_len, kCmds[c].name)) found = c;
  for (uint8_t i = 0; i < name_len; ++i) detail[i] = s[i];
  detail[name_len] = '\0';
  if (found < 0) return kErrUnknown;
  const CmdSpec& spec = kCmds[found];
  // Printable ASCII only in the fields.
  for (uint8_t i = name_len; i < n; ++i)
    if (s[i] < 0x20 || s[i] > 0x7E) return kErrArgs;
  // Fields.
  uint8_t nf = 0;
  uint8_t pos = name_len;
  Err worst = kOk;
  while (pos < n) {  // s[pos] == ','
    uint8_t start = static_cast<uint8_t>(pos + 1);
    uint8_t end = start;
    while (end < n && s[end] != ',') ++end;
    if (nf >= spec.nargs) return kErrArgs;
    const char* f = s + start;
    uint8_t fl = static_cast<uint8_t>(end - start);
    if (spec.kind == kInts) {
      Err e = parse_int(f, fl, &cmd->arg[nf]);
      if (e == kErrArgs) return kErrArgs;
      if (e == kErrRange) worst = kErrRange;
    } else if (spec.kind == kMode) {
      if (field_equals(f, fl, "BRAKE")) cmd->arg[nf] = 1;
      else if (field_equals(f, fl, "COAST")) cmd->arg[nf] = 0;
      else return kErrArgs;
    } else if (spec.kind == kDirs) {
      if (field_equals(f, fl, "FWD")) cmd->arg[nf] = 0;
      else if (field_equals(f, fl, "REV")) cmd->arg[nf] = 1;
      else return kErrArgs;
    } else if (spec.kind == kBit) {
      if (field_equals(f, fl, "0")) cmd->arg[nf] = 0;
      else if (field_equals(f, fl, "1")) cmd->arg[nf] = 1;
      else return kErrArgs;
    }
    ++nf;
    pos = end;
  }
  if (nf != spec.nargs) return kErrArgs;
  if (worst != kOk) return worst;
  cmd->id = static_cast<CmdId>(found);
  cmd->nargs = nf;
  detail[0] = '\0';
  return kOk;
}

}  // namespace minseg
