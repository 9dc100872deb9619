"""The words in the request's language: the gettext catalogue under ``locale/`` (every
msgid of :mod:`actuator_selection.phrases` and of the layers above), its rendering, and
the page's words exported from it (docs/i18n.md).
"""
