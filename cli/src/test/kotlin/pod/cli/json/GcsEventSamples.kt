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
    SurveyState(1, "executing", "forward", waypoint = 4, reason = null, eventId = 5, run = 1),
    SurveyPath(1, 3, listOf(SurveyPoint(41.1, -8.6), SurveyPoint(41.2, -8.6), SurveyPoint(41.2, -8.5)), listOf(SurveyPathPoint(41.1, -8.6, photo = true)), 30.0, 4, 40.0, 820.5, 1.2e4),
    SurveyOperatorCommand(1, "pause", 6, accepted = false, reason = "nothing to pause"),
    SurveyReport(1, "executing", "backward", 2, ready = null, reason = null, eventId = 6, counted = true),
    SurveyPhoto(1, 1, 4, 41.15, -8.55, listOf(3, 7), flagged = true, taken = true),
    SurveyBackward(1, 1, listOf(6, 2), listOf(SurveyMeasured(6, 30.4), SurveyMeasured(2, null))),
)
