"""pyserial URL handlers of minseg-tui: ``minseg://`` reaches a virtual MinSeg in-process.

pyserial looks a ``<scheme>://`` URL up as the module ``<package>.protocol_<scheme>`` in
each package of ``serial.protocol_handler_packages``, so the handler's module name,
``protocol_minseg``, is pyserial's rule; this package is what names it a URL handler.
:mod:`minseg_tui.device` registers the package when it is imported.
"""
