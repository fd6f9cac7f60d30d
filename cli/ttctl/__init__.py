"""ttctl: a toolchain for custom MAVLink 2 links over DJI Data Transparent Transmission."""

__version__ = "0.1.0"
