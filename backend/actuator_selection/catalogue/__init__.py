"""The catalogue: each value declared once (fields), the engine's record of an
actuator generated from them, the records, the file format and what a load changed.

Pure like ``sizing``: the standard library only.
"""
