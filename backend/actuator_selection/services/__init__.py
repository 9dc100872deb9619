"""The service's use cases, between the routers (HTTP) and the core (engineering).

A router parses the request and calls one function here; a use case reads and
writes through the repositories of ``db`` and computes with ``core``. Nothing here
knows HTTP.
"""
