"""Saving: the session file and its schema, the files on disk and the lock, recorded runs, the lab's file formats."""
