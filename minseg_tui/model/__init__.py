"""Models and identification: the motor, the plant simulation, the lab's computations and the model check.

numpy/scipy only; no I/O, no Textual.
"""
