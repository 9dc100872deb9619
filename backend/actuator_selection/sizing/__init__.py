"""The engineering of the chapter "Engineering Data for Harmonic Drive Servo Actuators".

Pure functions over frozen dataclasses: this package imports only the standard
library (and numpy on the vectorised batch path), never a web framework, an ORM
or a validation library, so that every number can be checked in isolation.
"""
