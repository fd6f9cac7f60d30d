"""Ground stations over the DTT link, sans-IO: the rules the tablet's bridge (`emulate tablet --gcs`,
the Java runtime's GcsBridge) and the onboard end follow.

- classes.py: which messages are a ground station's, which are newest-wins;
- uplink.py: the bridge's queue toward the vehicle (duplicates, newest-wins, a share of the uplink, bounds);
- routes.py: the bridge's ground-station peers, the vehicle's answers routed back, RADIO_STATUS;
- downfit.py: the onboard end's streams fitted to a share of the downlink.
"""
