"""The lab's content: its steps as data, the answers and how they are checked, formulas, reading an entry's quantity."""
