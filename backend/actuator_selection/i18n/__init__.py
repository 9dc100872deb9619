"""The words: the rules' codes and English templates (msgids), the gettext
catalogue under ``locale/``, its rendering in the request's language and the page's
words exported from it (docs/i18n.md).
"""
