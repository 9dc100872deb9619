"""Sizing service for Harmonic Drive servo actuators."""

__version__ = "0.1.0"
