"""Wire: MAVLink frames in DTT packets, on top of the generated bindings of the link's dialect
(`Bindings`: the user's dialect, or the shipped ttapi)."""
