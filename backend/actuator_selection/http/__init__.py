"""What every route shares (mounted by ``app.create_app``): the session
dependency, the one error shape, admission, API keys, security headers, methods, media types,
throttling, OpenAPI and the static pages.
"""
