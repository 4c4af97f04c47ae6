"""The lab session: the manual's steps as data, what a group enters and records, files and autosave."""
