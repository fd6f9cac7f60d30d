"""Wire: MAVLink frames in DTT packets, on top of the generated bindings (ttapi)."""
