"""The onboard computer's end: the vehicle it flies, the plugins it runs, and its links to the tablet
(DTT) and to ground stations (MAVLink over UDP)."""
