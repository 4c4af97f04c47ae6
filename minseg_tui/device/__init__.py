"""The board and the link: serial protocol, pyserial link, port discovery and the virtual MinSeg.

Importing this package registers the ``minseg://`` URL scheme with pyserial
(``serial.serial_for_url("minseg://?seed=1")`` reaches a virtual MinSeg).
"""

import serial

if "minseg_tui.device.url_handler" not in serial.protocol_handler_packages:
    serial.protocol_handler_packages.append("minseg_tui.device.url_handler")
