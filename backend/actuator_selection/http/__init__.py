"""The application (``app.create_app``) and what every route shares: the session
dependency, the one error shape, admission, security headers, methods, media types,
throttling, OpenAPI and the static pages.
"""
