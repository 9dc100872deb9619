"""Benchmarks: run with ``make bench``; they print ratios as well as absolute rates."""
