"""Browser tests of the engineer's web page (Playwright + Debian's Chromium)."""
