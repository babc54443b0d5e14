// Fuzz target: the parameter-file reader (core/io ParameterFile). Each input is read twice: as it
// is, and (when it is a JSON object) with its "checksum" recomputed, so that the fuzzer gets past
// the SHA-256 to the checks behind it. Bad input must end in a learnid::Error. An accepted file
// must write and read back to the same text, and give a DCF fragment.

#include "FuzzSupport.h"

#include "io/ParameterFile.h"
#include "model/Error.h"

#include <QJsonDocument>
#include <QJsonObject>

using namespace learnid;

namespace {

void readAndCheck(const QByteArray &json)
{
    ParameterFileContent content;
    try {
        content = parameterFileFromJson(json, QStringLiteral("fuzz.json"));
    } catch (const Error &) {
        return;
    }
    try {
        const QByteArray written = parameterFileToJson(content);
        const ParameterFileContent again =
            parameterFileFromJson(written, QStringLiteral("written.json"));
        if (parameterFileToJson(again) != written) {
            fuzz::fuzzFailure("a written parameter file reads back different",
                              QString::fromUtf8(written));
        }
        if (parameterDcfFragment(content).isEmpty())
            fuzz::fuzzFailure("an accepted parameter file gives no DCF fragment");
    } catch (const Error &e) {
        fuzz::fuzzFailure("an accepted parameter file cannot be written back", e.message());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::quietMessages();
    const QByteArray input = fuzz::bytes(data, size);
    readAndCheck(input);

    QJsonObject root = QJsonDocument::fromJson(input).object();
    if (root.isEmpty())
        return 0;
    root.remove(QStringLiteral("checksum"));
    root.insert(QStringLiteral("checksum"), QString::fromLatin1(parameterFileChecksum(root)));
    readAndCheck(QJsonDocument(root).toJson());
    return 0;
}
