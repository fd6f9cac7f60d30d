"""The tablet's end: what the Android app does with the link, scriptable."""
