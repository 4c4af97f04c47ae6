"""The app's screens: start (new or resume), the lab, help."""
