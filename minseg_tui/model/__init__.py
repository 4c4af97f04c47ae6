"""Models and identification: the motor, the plant simulation, the lab's computations and the model check.

numpy only; no I/O, no Textual.
"""
