// Fuzz target: the scenario reader (core/io ScenarioFile, JsonReader). Any input is read as a
// scenario file; bad input must end in a learnid::Error. An accepted scenario must write and
// read back to the same text.

#include "FuzzSupport.h"

#include "io/ScenarioFile.h"
#include "model/Error.h"

using namespace learnid;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::quietMessages();
    Scenario scenario;
    try {
        scenario = scenarioFromJson(fuzz::bytes(data, size), QStringLiteral("fuzz.json"));
    } catch (const Error &) {
        return 0;
    }
    const QByteArray written = scenarioToJson(scenario);
    try {
        const Scenario again = scenarioFromJson(written, QStringLiteral("written.json"));
        if (scenarioToJson(again) != written)
            fuzz::fuzzFailure("a written scenario reads back different",
                              QString::fromUtf8(written));
    } catch (const Error &e) {
        fuzz::fuzzFailure("a written scenario is refused", e.message());
    }
    return 0;
}
