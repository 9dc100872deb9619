"""The documents: the quote and the report, as HTML and as PDF, their figures
and the symbols they print.
"""
