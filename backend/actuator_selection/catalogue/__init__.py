"""The catalogue: each value declared once (fields), the engine's record of an
actuator generated from them, what the records are made of (parts, zones, Table
521.1's controllers), the records, the file format and what a load changed.

Pure like ``sizing``: the standard library only. It imports nothing of ``sizing``:
the engine reads the catalogue (``tests/test_purity.py``).
"""
