"""The two ends of the link (onboard, tablet) and their plugin system."""
