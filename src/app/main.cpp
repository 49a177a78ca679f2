// shadelab's entry point: the demo window (default), `render`, `reference` and `bench` (DESIGN §5), and the
// exit codes: 0 success, 2 bad input, 1 run-time failure.
#include <cstdio>
#include <exception>

#include "app/bench.h"
#include "app/cli.h"
#include "app/commands.h"
#include "app/report.h"
#include "shadelab/errors.h"

namespace {

using namespace shadelab;

// Runs what the command line asks for (its parsing lives in app/cli.cpp, where the fuzzer reaches it).
int run(int argc, char** argv) {
    const app::ParsedCommand command = app::parseCommandLine(argc, argv);
    using Kind = app::ParsedCommand::Kind;
    switch (command.kind) {
    case Kind::Exit:
        std::fputs(command.text.c_str(), stdout);
        return command.exitCode;
    case Kind::Render: {
        const Scene scene = app::composeScene(command.scene, command.overrides);
        const Backend backend = app::backendFromArgument(command.backend);
        app::checkOutputPath(command.out);
        return app::runRender(scene, backend, command.out, command.specialize);
    }
    case Kind::Bench: {
        app::BenchOptions bench = command.bench;
        Scene sized;
        app::composeSize(sized, command.benchSize);
        bench.width = sized.width;
        bench.height = sized.height;
        bench.backend = app::backendFromArgument(command.backend);
        if (!command.benchJson.empty()) {
            app::checkOutputPath(command.benchJson, "--json");
            bench.json = command.benchJson;
        }
        return app::runBench(bench);
    }
    case Kind::Reference: {
        const Scene scene = app::composeScene(command.scene, command.overrides);
        app::checkOutputPath(command.out);
        return app::runReference(scene, command.out);
    }
    case Kind::Report: {
        app::ReportOptions report;
        if (!command.scene.empty()) report.scene = command.scene;
        report.outDir = command.reportOut;
        app::parseLevels(command.reportLevels, report);
        report.includeAuto = !command.reportNoAuto;
        report.backend = app::backendFromArgument(command.backend);
        report.frames = command.reportFrames;
        report.warmup = command.reportWarmup;
        return app::runReport(report);
    }
    case Kind::Demo:
        break;
    }
    app::checkOutputPath(command.demo.showcaseOut, "--showcase-out");
    return app::runDemo(app::composeScene(command.scene, command.overrides), command.demo);
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "shadelab: %s\n", e.what());
        return kExitInputError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadelab: %s\n", e.what());
        return kExitRuntimeError;
    }
}
