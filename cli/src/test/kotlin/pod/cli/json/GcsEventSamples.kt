package pod.cli.json

/** One of each event only `pod gcs` sends its pages, for EventJsonTest's samples of every kind. */
internal val gcsEventSamples: List<Event> = listOf(
    GcsHello("4 simulated copters", tiles = "https://tiles.example/{z}/{x}/{y}.png", timeScale = 5.0, batchesPerSecond = 10),
    GcsBatch(7, listOf(Event.Found(1, 1, "QUADROTOR", "ARDUPILOT"), Reply(3, ok = true, detail = "pong"))),
    Reply(4, ok = false, error = "vehicle 1 refused: Arm: Mode not armable"),
    Home(1, 41.1, -8.6, 95.0),
    VehicleStatus(1, awaiting = "MAV_CMD_NAV_TAKEOFF", text = "PreArm: GPS not healthy", severity = "CRITICAL"),
    VehicleText(1, "WARNING", "Arm: Mode not armable"),
    PageAction(1, "takeoff", "ok", "15 m"),
    QueueFlightState(1, flying = false, error = "vehicle 1 was lost"),
)
