#include "drive.h"

namespace minseg {

uint8_t duty_counts(int32_t u_mV, uint16_t vsupply_mV) {
  if (vsupply_mV == 0) return 0;
  uint32_t mag = u_mV < 0 ? static_cast<uint32_t>(-(u_mV + 1)) + 1u : static_cast<uint32_t>(u_mV);
  if (mag >= vsupply_mV) return kPwmTop;
  // mag < vsupply <= 65535, so mag * 255 fits in 32 bits
  uint32_t d = (mag * kPwmTop + vsupply_mV / 2u) / vsupply_mV;
  return static_cast<uint8_t>(d > kPwmTop ? kPwmTop : d);
}

BridgeLevels bridge_levels(int32_t u_mV, uint16_t vsupply_mV, bool brake) {
  uint8_t d = duty_counts(u_mV, vsupply_mV);
  BridgeLevels out;
  if (brake) {
    uint8_t off = static_cast<uint8_t>(kPwmTop - d);
    out.a = u_mV < 0 ? off : kPwmTop;
    out.b = u_mV > 0 ? off : kPwmTop;
  } else {
    out.a = u_mV > 0 ? d : 0;
    out.b = u_mV < 0 ? d : 0;
  }
  return out;
}

}  // namespace minseg
