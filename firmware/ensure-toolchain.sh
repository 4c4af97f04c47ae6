#!/bin/sh
# Makes sure the AVR cross toolchain for `make -C firmware` is present.
# Present: exit 0. Missing and root: install it with apt-get. Missing and not
# root: say what is missing and how to install it, exit 2.
# simavr (optional: the handshake test of the built binary) is installed
# along with the toolchain when running as root.

missing=""
command -v avr-g++ >/dev/null 2>&1 || missing="$missing gcc-avr"
command -v avr-objcopy >/dev/null 2>&1 || missing="$missing binutils-avr"
command -v avr-size >/dev/null 2>&1 || case "$missing" in *binutils-avr*) ;; *) missing="$missing binutils-avr" ;; esac
[ -f /usr/lib/avr/include/avr/io.h ] || [ -f /usr/avr/include/avr/io.h ] || missing="$missing avr-libc"

simavr_missing=""
ls /usr/lib/*/libsimavr.so* /usr/lib/libsimavr.so* /usr/local/lib/libsimavr.so* >/dev/null 2>&1 || simavr_missing="simavr"

if [ -z "$missing" ]; then
    if [ -n "$simavr_missing" ] && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        apt-get install -y simavr >/dev/null 2>&1 || true
    fi
    exit 0
fi

if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "ensure-toolchain: installing$missing $simavr_missing"
    apt-get update && apt-get install -y gcc-avr avr-libc binutils-avr $simavr_missing
    exit $?
fi

echo "error: the AVR cross toolchain is missing (needed:$missing)." >&2
echo "  install it with: sudo apt-get install gcc-avr avr-libc binutils-avr simavr" >&2
echo "  or run the tests without the firmware cross-build: make test AVR=0" >&2
exit 2
