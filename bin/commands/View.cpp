// `ropras view`: one self-contained HTML page (three.js inline) showing a recorded episode or a planned motion in 3-D.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"
#include "ropras/scenarios/EpisodeView.h"
#include "ropras/scenarios/MotionView.h"
#include "ropras/scenarios/SvgRenderer.h"
#include "ropras/scenarios/ViewerPage.h"

namespace
{
    struct ViewOptions
    {
        std::string recording;
        std::string urdf, srdf, scene, path;
        std::string out;
        std::string three{ropras::scenarios::DEFAULT_THREE_DIR};
        std::string tip;
        double step{0.05};
    };

    std::string folderOf(const std::string &file)
    {
        const auto slash = file.rfind('/');
        return slash == std::string::npos ? std::string(".") : file.substr(0, slash);
    }

    std::string baseName(const std::string &file)
    {
        const auto slash = file.rfind('/');
        return slash == std::string::npos ? file : file.substr(slash + 1);
    }

    /** \brief "dir/name.json" -> "dir/name.html". */
    std::string defaultOut(const std::string &input)
    {
        const auto dot = input.rfind('.');
        const auto slash = input.rfind('/');
        const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
        return (hasExtension ? input.substr(0, dot) : input) + ".html";
    }

    nlohmann::json motionDocument(const ViewOptions &o)
    {
        using namespace ropras::ompl_ext;
        const auto robot = RobotModel::fromUrdfFile(o.urdf, o.srdf);
        const Environment environment = o.scene.empty() ? Environment() : loadPlanningScene(o.scene, robot);
        const auto path = ropras::scenarios::loadJointPathCsv(o.path, *robot);
        ropras::scenarios::MotionViewOptions options;
        options.title = robot->name() + ": " + baseName(o.path);
        options.subtitle = std::to_string(path.size()) + " waypoints" +
                           (o.scene.empty() ? std::string(", no scene") : ", scene " + baseName(o.scene));
        options.maxJointStep = o.step;
        options.tipLink = o.tip;
        return ropras::scenarios::motionView(*robot, environment, path, options);
    }

    int run(const ViewOptions &o)
    {
        const bool motion = !o.path.empty() || !o.urdf.empty();
        if (motion == !o.recording.empty())
        {
            throw ropras::Error(
                "view: give either a recording (ropras view RECORDING.json) or a motion (--urdf U "
                "--path PATH.csv [--scene SCENE.yaml])");
        }
        if (motion && (o.urdf.empty() || o.path.empty()))
        {
            throw ropras::Error("view: a motion needs both --urdf and --path (and optionally --scene, --srdf)");
        }
        const std::string out = !o.out.empty() ? o.out : defaultOut(motion ? o.path : o.recording);
        ropras::bin::refuseOverwritingInputs("--out", out, {o.recording, o.urdf, o.srdf, o.scene, o.path});
        const auto three = ropras::scenarios::loadThreeJs(o.three);
        nlohmann::json view;
        if (motion)
        {
            view = motionDocument(o);
        }
        else
        {
            const auto recording = ropras::scenarios::loadRecording(o.recording);
            view = ropras::scenarios::episodeView(recording, o.recording, folderOf(o.recording));
        }
        const std::string page = ropras::scenarios::viewerPage(view, three);
        std::ofstream file(out, std::ios::binary);
        file << page;
        file.close();
        if (!file)
        {
            throw ropras::Error("--out: cannot write \"" + out + "\"");
        }
        std::cout << "wrote " << out << " (" << page.size() / 1024 << " KiB, " << view["frames"].get<std::size_t>()
                  << " frames)\n";
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<ViewOptions>();
        app.add_option("recording", o->recording, "Episode recording written by `ropras run --record DIR`")
            ->check(CLI::ExistingFile);
        app.add_option("--urdf", o->urdf, "robot URDF of a motion")->check(CLI::ExistingFile);
        app.add_option("--srdf", o->srdf, "SRDF of the robot")->check(CLI::ExistingFile);
        app.add_option("--scene", o->scene, "MoveIt PlanningScene YAML of a motion")->check(CLI::ExistingFile);
        app.add_option("--path", o->path, "joint-space path CSV written by `ropras plan --out`")
            ->check(CLI::ExistingFile);
        app.add_option("--out", o->out, "HTML file (default: the input's name with .html)");
        app.add_option("--three", o->three, "folder holding three.min.js and examples/js/controls/OrbitControls.js")
            ->capture_default_str();
        app.add_option("--step", o->step, "largest joint change between two frames of a motion (rad or m)")
            ->capture_default_str()
            ->check(ropras::bin::numberCheck(0.0, true, false, "STEP > 0", 100.0));
        app.add_option("--tip", o->tip, "link whose path a motion draws (default: the last planning joint's child)");
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"view", "Write one self-contained HTML page showing a recorded episode or a planned motion in 3-D", setup}};
}  // namespace
