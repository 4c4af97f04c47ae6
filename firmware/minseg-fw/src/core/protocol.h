// Protocol version 3 (firmware/PROTOCOL.md): framing, checksums, number
// formatting, the line assembler and the command parser.
// Board-independent: no Arduino or AVR headers, no dynamic memory.
#ifndef MINSEG_PROTOCOL_H
#define MINSEG_PROTOCOL_H

#include <stdint.h>

namespace minseg {

static const uint8_t kProtoVersion = 3;
static const uint8_t kMaxLine = 80;  // longest accepted line, without "\r\n"

// The frame checksum of n bytes (the bytes between '$' and '*'): CRC-16/CCITT-FALSE,
// polynomial 0x1021, initial value 0xFFFF, no reflection, no final XOR, sent as four
// hex digits. It catches every swap of two adjacent bytes and every burst error up
// to 16 bits (protocol 1's XOR let most of them through). Table-free: a few shifts
// and XORs per byte, no RAM or flash table.
uint16_t crc16_update(uint16_t crc, uint8_t byte);
uint16_t checksum(const char* s, uint8_t n);
static const uint8_t kChecksumDigits = 4;

// Decimal text of v into out (no terminator); returns the number of bytes.
uint8_t format_u32(uint32_t v, char* out);
uint8_t format_i32(int32_t v, char* out);

// Builds one board line: $NAME,field,...*CS\n. Capacity fits every line the
// board sends (the longest, $ID, is about 60 bytes).
class LineWriter {
 public:
  static const uint8_t kCap = 88;
  explicit LineWriter(const char* name);
  LineWriter& str(const char* s);
  LineWriter& u32(uint32_t v);
  LineWriter& i32(int32_t v);
  // Appends *CS\n; returns the finished line (not NUL-terminated: use len()).
  const char* finish();
  uint8_t len() const { return n_; }

 private:
  void put(char c);
  char buf_[kCap];
  uint8_t n_;
};

// Collects bytes into lines. A '\r' just before '\n' is dropped; a line of
// more than kMaxLine bytes is discarded whole and reported once at its '\n'.
class LineAssembler {
 public:
  enum Status { kNone, kLine, kOverlong };
  LineAssembler() : n_(0), overlong_(false), ready_(false) {}
  Status feed(char c);
  const char* line() const { return buf_; }  // valid after kLine
  uint8_t len() const { return n_; }

 private:
  char buf_[kMaxLine + 2];
  uint8_t n_;
  bool overlong_;
  bool ready_;
};

enum Err { kOk = 0, kErrChecksum, kErrUnknown, kErrArgs, kErrRange, kErrBusy, kIgnore };
const char* err_name(Err e);

enum CmdId { kId, kPing, kV, kStep, kStop, kP, kZ, kSup, kZm, kStream, kDir, kDiag, kCmdCount };
const char* cmd_name(CmdId c);

struct Command {
  CmdId id;
  uint8_t nargs;
  int32_t arg[4];  // ZM: arg[0] = 1 for BRAKE, 0 for COAST; STREAM: 0 or 1;
                   // DIR: arg[0], arg[1] = 1 for REV, 0 for FWD
};

// Parses one host line (without '\n'). Returns kOk and fills cmd, or an
// error. On kErrArgs/kErrRange/kErrUnknown, detail receives the command name
// when it is a well-formed name (else ""); detail must hold 12 bytes.
// An empty line gives kIgnore.
Err parse_command(const char* line, uint8_t len, Command* cmd, char* detail);

}  // namespace minseg

#endif
