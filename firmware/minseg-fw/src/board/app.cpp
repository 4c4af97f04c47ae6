#include "app.h"

#include <avr/interrupt.h>

#include "../core/controller.h"
#include "../core/drive.h"
#include "hal.h"
#include "profile.h"

namespace {

class AvrBoard : public minseg::Board {
 public:
  uint8_t connectors() override { return hal_connectors(); }
  int32_t encoder_count(uint8_t i) override { return hal_encoder_count(i); }
  uint32_t encoder_edges(uint8_t i) override { return hal_encoder_edges(i); }
  uint8_t encoder_pins(uint8_t i) override { return hal_encoder_pins(i); }
  void encoder_zero() override { hal_encoder_zero(); }
  void set_direction(uint8_t dir) override {
    hal_set_direction((dir & minseg::kDirEncoderRev) != 0, (dir & minseg::kDirMotorRev) != 0);
  }
  uint8_t load_direction() override { return hal_load_direction(); }
  void save_direction(uint8_t dir) override { hal_save_direction(dir); }
  void drive(int32_t u_mV, uint16_t vsupply_mV, bool brake) override {
    minseg::BridgeLevels l = minseg::bridge_levels(u_mV, vsupply_mV, brake);
    hal_bridge(l.a, l.b);
  }
  bool send(const char* s, uint8_t n, bool droppable) override {
    if (droppable && hal_uart_tx_free() < n) return false;  // never stall for a sample
    hal_uart_write(s, n);
    return true;
  }
};

AvrBoard board;
minseg::Controller controller(&board, MINSEG_BOARD_NAME);

}  // namespace

extern "C" void __cxa_pure_virtual() {
  for (;;) {
  }
}

void minseg_setup() {
  cli();
  hal_init();
  sei();
  controller.begin(hal_micros());
}

void minseg_loop() {
  int16_t c;
  uint8_t budget = 32;  // bytes per pass, so a flood cannot starve the schedule
  while (budget-- > 0 && (c = hal_uart_getc()) >= 0)
    controller.feed(static_cast<char>(c), hal_micros());
  controller.poll(hal_micros());
  hal_poll();
}
