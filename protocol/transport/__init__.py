"""Links between the station and a device: serial, BLE and the in-process loopback."""
