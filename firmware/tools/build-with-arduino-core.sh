#!/bin/sh
# Builds the sketch the way the Arduino IDE would (minseg-fw.ino with
# Arduino.h, the sketch's src/ tree, linked against the Arduino AVR core), using
# Debian's arduino-core-avr and gcc-avr 5.4. Debian's core does not compile
# WString.cpp with gcc-avr 5.4 (DECIMAL_DIG undeclared); the sketch uses no
# String, so the core is built without WString.cpp.
# Usage: tools/build-with-arduino-core.sh OUTDIR [PROFILE_DEFINE]
set -e
OUT=${1:?usage: $0 OUTDIR [MINSEG_PROFILE_...]}
PROFILE_DEF=${2:-MINSEG_PROFILE_MINSEGMEGA}
ARDUINO=${ARDUINO_DIR:-/usr/share/arduino/hardware/arduino/avr}
CORE=$ARDUINO/cores/arduino
VAR=$ARDUINO/variants/mega
[ -d "$CORE" ] || { echo "error: Arduino AVR core not found in $CORE (Debian: apt-get install arduino-core-avr)" >&2; exit 2; }
cd "$(dirname "$0")/.."
mkdir -p "$OUT"
F="-mmcu=atmega2560 -DF_CPU=16000000L -DARDUINO=10800 -DARDUINO_AVR_MEGA2560 -DARDUINO_ARCH_AVR -Os -ffunction-sections -fdata-sections -I$CORE -I$VAR"
CXXF="-std=gnu++11 -fno-exceptions -fno-threadsafe-statics"
objs=""
for f in "$CORE"/*.c; do
    avr-gcc -c $F -std=gnu11 -w "$f" -o "$OUT/core_$(basename "$f").o"; objs="$objs $OUT/core_$(basename "$f").o"
done
for f in "$CORE"/*.cpp; do
    case $f in */WString.cpp) continue ;; esac
    avr-g++ -c $F $CXXF -w "$f" -o "$OUT/core_$(basename "$f").o"; objs="$objs $OUT/core_$(basename "$f").o"
done
avr-gcc -c $F -x assembler-with-cpp "$CORE/wiring_pulse.S" -o "$OUT/core_wiring_pulse.S.o"
objs="$objs $OUT/core_wiring_pulse.S.o"
rm -f "$OUT/core.a"
avr-ar rcs "$OUT/core.a" $objs
{ echo '#include <Arduino.h>'; echo '#line 1 "minseg-fw.ino"'; cat minseg-fw/minseg-fw.ino; } > "$OUT/minseg-fw.ino.cpp"
sk="$OUT/minseg-fw.ino.o"
avr-g++ -c $F $CXXF -Wall -Wextra -D$PROFILE_DEF -Iminseg-fw "$OUT/minseg-fw.ino.cpp" -o "$OUT/minseg-fw.ino.o"
for f in minseg-fw/src/core/*.cpp minseg-fw/src/board/*.cpp; do
    avr-g++ -c $F $CXXF -Wall -Wextra -Werror -D$PROFILE_DEF "$f" -o "$OUT/sketch_$(basename "$f").o"
    sk="$sk $OUT/sketch_$(basename "$f").o"
done
avr-gcc -mmcu=atmega2560 -Os -Wl,--gc-sections $sk "$OUT/core.a" -lm -o "$OUT/minseg-fw.elf"
avr-objcopy -O ihex -R .eeprom "$OUT/minseg-fw.elf" "$OUT/minseg-fw.hex"
echo "== Arduino-core build ($PROFILE_DEF): ATmega2560 flash and RAM use"
avr-size -C --mcu=atmega2560 "$OUT/minseg-fw.elf" | grep -E "Program|Data"
