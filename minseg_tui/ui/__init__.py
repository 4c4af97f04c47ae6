"""The Textual user interface: screens and widgets that render lab state and post messages."""
