"""The link: a model of DJI's DTT radio link (profiles, loss, pacing) in virtual or real time,
and the transports (UDP/TCP) between processes. It knows packets, not MAVLink messages."""
