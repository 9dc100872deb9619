"""The service's use cases, between the routers (HTTP) and the domain.

A router parses the request and calls one function here; a use case reads and
writes through the repositories of ``db`` and computes with the domain (``sizing``,
``catalogue``, ``sales``). Nothing here knows HTTP.
"""
