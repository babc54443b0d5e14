#include "can/BusLoad.h"

#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(BusLoad)
};

} // namespace

QString BusLoad::text(double bitrate) const
{
    return Text::tr("%1 % of %2 kbit/s (%3 frames/s)")
        .arg(percent, 0, 'f', 1)
        .arg(bitrate / 1000.0, 0, 'f', 0)
        .arg(framesPerSecond, 0, 'f', 0);
}

int worstCaseFrameBits(int dlc, bool extended)
{
    const int n = qBound(0, dlc, 8);
    // g: the bits subject to stuffing besides the data (34 standard, 54 extended); the 13 that
    // are not stuffed are the CRC delimiter, ACK, EOF and the 3 bits of interframe space.
    const int g = extended ? 54 : 34;
    return g + 8 * n + 13 + (g + 8 * n - 1) / 4;
}

BusLoad estimateBusLoad(const BusLoadConfig &config)
{
    if (config.joints < 0 || config.framesPerJointPerSample < 0 || !(config.sampleRate > 0) ||
        !(config.bitrate > 0) || config.payloadBytes < 0 || config.payloadBytes > 8 ||
        config.syncPayloadBytes < 0 || config.syncPayloadBytes > 8) {
        throw Error(
            Text::tr("Bus load: joints and frames must not be negative, rates must be positive "
                     "and a frame carries 0 to 8 bytes."));
    }
    const int pdoFrames = config.joints * config.framesPerJointPerSample;
    const int framesPerSample = pdoFrames + (config.sync ? 1 : 0);
    const int bitsPerSample = pdoFrames * worstCaseFrameBits(config.payloadBytes) +
                              (config.sync ? worstCaseFrameBits(config.syncPayloadBytes) : 0);
    BusLoad load;
    load.framesPerSecond = framesPerSample * config.sampleRate;
    load.bitsPerSecond = bitsPerSample * config.sampleRate;
    load.percent = 100.0 * load.bitsPerSecond / config.bitrate;
    return load;
}

BusLoad measureBusLoad(const QList<QCanBusFrame> &frames, double seconds, double bitrate)
{
    if (!(seconds > 0) || !(bitrate > 0))
        throw Error(Text::tr("Bus load: the time window and the bitrate must be positive."));
    double bits = 0;
    for (const QCanBusFrame &f : frames) {
        const int dlc =
            f.frameType() == QCanBusFrame::RemoteRequestFrame ? 0 : int(f.payload().size());
        bits += worstCaseFrameBits(dlc, f.hasExtendedFrameFormat());
    }
    BusLoad load;
    load.framesPerSecond = frames.size() / seconds;
    load.bitsPerSecond = bits / seconds;
    load.percent = 100.0 * load.bitsPerSecond / bitrate;
    return load;
}

} // namespace learnid
