"""Numbers as people type them, per language: one table for the Qt side's reader and the page's."""

READ = [("de", "2,5", 2.5), ("de", "-0,25", -0.25), ("de", "1.000", 1000), ("de", "1.000,5", 1000.5),
        ("de", ",5", 0.5), ("de", "3", 3), ("de", " 7 ", 7), ("en", "2.5", 2.5), ("en", "1,000", 1000),
        ("en", "1,000.5", 1000.5), ("en", "-.5", -0.5), ("en", "1e3", 1000.0), ("en", "\u22124", -4)]
"""(language, typed, the number read): shared with the page's reader's test."""

REFUSED = [("en", "2,5"), ("en", "1,5000"), ("en", "1,00"), ("en", "12,34,567"), ("de", "2.5"), ("de", "1,000,5"),
           ("en", ""), ("en", "-"), ("en", "."), ("en", "e3"), ("en", "abc"), ("en", "2.5.1")]
"""(language, typed): texts that are no number, or could be read two ways."""
