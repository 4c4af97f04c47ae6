"""Views for the screens and the report: one session's, the class's, as plain data."""
