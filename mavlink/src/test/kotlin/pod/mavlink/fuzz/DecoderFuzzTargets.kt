package pod.mavlink.fuzz

/**
 * Every decoder Pod has, as fuzz targets over one corpus: CI runs each for 100k inputs
 * ([DecoderFuzzTest]), the soak run (`bench/fuzz.sh`) for 10 million. A new decoder, or a new path
 * to one (a station's signed receive path: `SignedFrameReceive(corpus, "station-signed") { key -> … }`),
 * is one more line here.
 */
public object DecoderFuzzTargets {
    /** Fresh targets over [corpus], in report order. */
    public fun all(corpus: FuzzCorpus): List<FuzzTarget> = listOf(
        DatagramDecoding(corpus),
        StreamDecoding(corpus),
        SignedFrameReceive(corpus),
        TlogReading(corpus),
    )
}
