package pod.mavlink.mission

/**
 * Checks a list before it is uploaded, so the vehicle is never sent what it must refuse.
 * [MissionService] runs it on every upload; a caller with a file to send runs it first to refuse
 * the file before any link is opened.
 */
public object MissionValidation {
    /**
     * The most items one list holds: MISSION_COUNT's count is a uint16, so seq runs 0..65534.
     * [WplFile] reads no more than this.
     */
    public const val MAX_ITEMS: Int = 65_535

    private val fenceCommands = setOf(5000, 5001, 5002, 5003, 5004)
    private const val RALLY_POINT = 5100

    /**
     * Throws [InvalidMission] naming the first item that cannot be sent as a [type] list ([first]:
     * the seq of the first of [items], for a partial write).
     */
    public fun check(type: MissionType, items: List<MissionItem>, first: Int = 0) {
        if (first + items.size > MAX_ITEMS) {
            throw InvalidMission(type, MAX_ITEMS, "at most $MAX_ITEMS items fit a MISSION_COUNT, the list has ${first + items.size}")
        }
        var currents = 0
        items.forEachIndexed { index, item ->
            fun fail(reason: String): Nothing = throw InvalidMission(type, first + index, reason)
            if (item.seq != first + index) fail("seq must be ${first + index} (items are numbered from $first without gaps), was ${item.seq}")
            if (item.missionType != type) fail("belongs to the ${item.missionType.name.lowercase()} list, not ${type.name.lowercase()}")
            if (item.current) currents++
            if (item.frame !in 0..255) fail("frame must be 0..255, was ${item.frame}")
            if (item.command !in 0..65535) fail("command must be 0..65535, was ${item.command}")
            if (item.isGlobal) {
                if (item.x !in -900_000_000..900_000_000) fail("latitude must be in -90..90, was ${item.latitude}")
                if (item.y !in -1_800_000_000..1_800_000_000) fail("longitude must be in -180..180, was ${item.longitude}")
            }
            if (!item.z.isFinite()) fail("z (altitude) must be a finite number, was ${item.z}")
            when (type) {
                MissionType.MISSION -> if (item.frame !in MissionItem.GLOBAL_FRAMES && item.frame !in MissionItem.LOCAL_FRAMES &&
                    item.frame != MissionItem.FRAME_MISSION
                ) {
                    fail("frame ${item.frame} is not a MAV_FRAME a mission item can use")
                }
                MissionType.FENCE -> {
                    if (item.command !in fenceCommands) fail("command ${item.command} is not a fence command (5000..5004)")
                    if (!item.isGlobal) fail("fence items need a global frame, was ${item.frame}")
                }
                MissionType.RALLY -> {
                    if (item.command != RALLY_POINT) fail("command ${item.command} is not NAV_RALLY_POINT (5100)")
                    if (!item.isGlobal) fail("rally points need a global frame, was ${item.frame}")
                }
            }
            if (currents > 1) fail("a second item marked current (only one may be)")
            if (type != MissionType.MISSION && item.current) fail("${type.name.lowercase()} items cannot be current")
        }
    }
}
