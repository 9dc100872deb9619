"""The sales rules: money, price lists, quote status and terms, the records.

Pure like ``sizing``: the standard library only.
"""
