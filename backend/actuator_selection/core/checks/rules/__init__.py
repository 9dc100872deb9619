"""The checks, one family to a file, each rule with its words."""
