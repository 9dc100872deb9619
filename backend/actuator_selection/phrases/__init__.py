"""The domain's words as codes: each rule's stable code and its English template (the
msgid), marked ``N_("…")``; pure, imported by the domain. Rendering them in the
request's language is :mod:`actuator_selection.i18n`'s (docs/i18n.md).
"""
