// `ropras render RECORDING.json`: an SVG picture of an episode recorded with `ropras run --record`.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/SvgRenderer.h"

namespace
{
    struct RenderOptions
    {
        std::string recording;
        std::string out;
        std::string steps;
        std::string armSteps;
        double width{800.0};
    };

    /** \brief "0,50,100" -> {0, 50, 100}; throws ropras::Error naming the entry that is not a whole number. */
    std::vector<std::size_t> stepList(const std::string &text, const std::string &option = "--steps")
    {
        std::vector<std::size_t> out;
        std::size_t begin = 0;
        while (begin <= text.size())
        {
            const std::size_t comma = std::min(text.find(',', begin), text.size());
            const std::string item = text.substr(begin, comma - begin);
            const bool digits =
                !item.empty() && item.size() <= 18 && item.find_first_not_of("0123456789") == std::string::npos;
            if (!digits)
            {
                throw ropras::Error(option + " \"" + text + "\": \"" + item +
                                    "\" is not a step number (expected e.g. 0,50,100)");
            }
            out.push_back(static_cast<std::size_t>(std::stoull(item)));
            begin = comma + 1;
        }
        return out;
    }

    int run(const RenderOptions &o)
    {
        ropras::scenarios::SvgOptions options;
        options.width = o.width;
        if (!o.steps.empty())
        {
            options.beliefSteps = stepList(o.steps);
        }
        if (!o.armSteps.empty())
        {
            options.armSteps = stepList(o.armSteps, "--arm-steps");
        }
        ropras::bin::refuseOverwritingInputs("--out", o.out, {o.recording});
        const auto recording = ropras::scenarios::loadRecording(o.recording);
        const std::string svg = ropras::scenarios::renderSvg(recording, options, o.recording);
        std::string out = o.out;
        if (out.empty())
        {
            const auto dot = o.recording.rfind('.');
            const auto slash = o.recording.rfind('/');
            out = (dot != std::string::npos && (slash == std::string::npos || dot > slash) ? o.recording.substr(0, dot)
                                                                                           : o.recording) +
                  ".svg";
        }
        ropras::bin::refuseOverwritingInputs("--out", out, {o.recording});
        std::ofstream file(out);
        file << svg;
        if (!file)
        {
            throw ropras::Error("--out: cannot write \"" + out + "\"");
        }
        std::cout << "wrote " << out << '\n';
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<RenderOptions>();
        app.add_option("recording", o->recording, "Episode recording written by `ropras run --record DIR`")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--out", o->out, "SVG file (default: the recording's name with .svg)");
        app.add_option("--steps", o->steps, "Belief steps to draw, e.g. 0,50,100 (default: every recorded belief)");
        app.add_option(
            "--arm-steps", o->armSteps,
            "Steps at which a recorded robot (an arm) is drawn posed and the scene's objects (cans) are drawn, e.g. "
            "0,20,40 (default: 6 spread evenly)");
        app.add_option("--width", o->width, "Width of the map in pixels")
            ->capture_default_str()
            ->check(ropras::bin::numberCheck(50.0, false, false, "WIDTH >= 50", 100000.0));
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"render",
         "Draw an episode recorded by `ropras run --record` as an SVG picture (top view; 3-D problems add a side view)",
         setup}};
}  // namespace
