// SPDX-License-Identifier: GPL-3.0-or-later
//! \file meshlab_runner.cpp
//! meshbridge-mlrun: a headless runner for MeshLab >= 2022 (there is no meshlabserver any more),
//! doing what pymeshlab does with MeshLab's own libmeshlab-common.so: plugins are loaded by
//! MeshLab's PluginManager (so its version and precision checks apply), meshes are loaded into a
//! MeshDocument by MeshLab's IO plugins, filters are looked up by their python names in
//! pymeshlab's FunctionSet, parameters are set by python name on the filter's own
//! RichParameterList, applyFilter's result map is printed, and layers are saved by the IO plugins.
//!
//!   meshbridge-mlrun [--no-precondition-check] STEP...
//!
//! Steps run in order; a `key=value` word belongs to the step before it.
//!   plugin FILE              load one plugin (libio_base.so for OBJ/OFF/PLY, ours, ...)
//!   plugins DIR              load every plugin in DIR
//!   version                  MeshLab's version (libmeshlab-common.so) and each loaded plugin's
//!                            getMLVersion(): "plugin <file> version=<v> precision=<float|double>"
//!   list                     every filter: "filter <python name> (<MeshLab name>)", then one
//!                            "  <parameter> : <python type> = <default>" line per parameter
//!   load FILE                load a mesh into a new layer, made current
//!   filter NAME [k=v...]     apply the filter with python name NAME; prints MeshLab's log of
//!                            the filter ("log: ...") and the result map ("result: key=value")
//!   save FILE [layer=current|last|<id>] [attributes=vc,vq,vf,vn,vt,fc,fq,ff,fn,wt|default]
//!            [binary=true|false] save one layer; attributes as meshlabserver's -m (default: the
//!                            format's defaults), binary as the PLY/STL "Binary" option; an
//!                            empty layer is not saved (MeshLab's exporters refuse it)
//!   layers                   "layers: N", then "layer <id> '<label>' <vn> <fn> <en>" per layer
//!
//! --no-precondition-check calls applyFilter even when FilterPlugin::isFilterApplicable() says
//! no (pymeshlab refuses first), to test a filter's own errors.
//! Exit status: 0, or 1 with "error: <message>" on stderr (an MLException, like pymeshlab's
//! PyMeshLabException), or 2 for bad usage.

#include <common/globals.h>
#include <common/ml_document/mesh_document.h>
#include <common/mlexception.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/plugin_manager.h>
#include <common/python/function_set.h>
#include <common/python/python_utils.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

struct Step {
  std::string name;
  std::vector<std::string> args;                             //!< plain words
  std::vector<std::pair<std::string, std::string>> options;  //!< key=value words
};

const std::vector<std::string> kStepNames = {"plugin", "plugins", "version", "list",
                                             "load",   "filter",  "save",    "layers"};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "meshbridge-mlrun: " << why << "\n"
            << "usage: meshbridge-mlrun [--no-precondition-check] STEP...\n"
               "  plugin FILE | plugins DIR | version | list | load FILE |\n"
               "  filter PYTHON_NAME [param=value...] |\n"
               "  save FILE [layer=current|last|ID] [attributes=vc,vq,vf,vn,vt,fc,fq,ff,fn,wt] "
               "[binary=true|false] | layers\n";
  std::exit(2);
}

bool is_step(const std::string& word) {
  for (const std::string& s : kStepNames)
    if (word == s)
      return true;
  return false;
}

bool parse_bool(const QString& key, const std::string& value) {
  if (value == "true" || value == "True" || value == "1")
    return true;
  if (value == "false" || value == "False" || value == "0")
    return false;
  throw MLException("Parameter " + key + ": '" + QString::fromStdString(value) +
                    "' is not a bool (true/false)");
}

double parse_number(const QString& key, const std::string& value) {
  bool ok = false;
  const double v = QString::fromStdString(value).toDouble(&ok);
  if (!ok)
    throw MLException("Parameter " + key + ": '" + QString::fromStdString(value) +
                      "' is not a number");
  return v;
}

//! Sets one parameter from its text, by the parameter's MeshLab type (what pymeshlab does with a
//! python value).
void set_parameter(RichParameter& par, const std::string& value) {
  const QString key = par.pythonName();
  if (par.isOfType<RichBool>()) {
    par.setValue(BoolValue(parse_bool(key, value)));
  } else if (par.isOfType<RichEnum>()) {
    RichEnum& en = dynamic_cast<RichEnum&>(par);
    int index = en.enumvalues.indexOf(QString::fromStdString(value));
    if (index < 0) {
      bool ok = false;
      index = QString::fromStdString(value).toInt(&ok);
      if (!ok || index < 0 || index >= en.enumvalues.size())
        throw MLException("Parameter " + key + ": '" + QString::fromStdString(value) +
                          "' is neither one of " + en.enumvalues.join("; ") +
                          " nor an index below " + QString::number(en.enumvalues.size()));
    }
    par.setValue(IntValue(index));
  } else if (par.isOfType<RichInt>() || par.isOfType<RichMesh>()) {
    par.setValue(IntValue(int(parse_number(key, value))));
  } else if (par.isOfType<RichFloat>() || par.isOfType<RichDynamicFloat>() ||
             par.isOfType<RichPercentage>()) {
    par.setValue(FloatValue(Scalarm(parse_number(key, value))));
  } else if (par.isOfType<RichString>() || par.isOfType<RichFileOpen>() ||
             par.isOfType<RichFileSave>()) {
    par.setValue(StringValue(QString::fromStdString(value)));
  } else {
    throw MLException("Parameter " + key + ": type " + par.stringType() +
                      " is not supported by this runner");
  }
}

//! A result value as pymeshlab's toPyDict() converts it.
std::string result_text(const QVariant& v) {
  const std::string type = v.typeName() ? v.typeName() : "";
  if (type == "int")
    return std::to_string(v.toInt());
  if (type == "bool")
    return v.toBool() ? "True" : "False";
  if (type == "double" || type == "float")
    return QString::number(v.toDouble(), 'g', 10).toStdString();
  return "<" + type + ">";
}

class Runner {
 public:
  explicit Runner(bool check_preconditions) : check_preconditions_(check_preconditions) {}

  void run(const Step& step) {
    if (step.name == "plugin") {
      need_args(step, 1);
      load_plugin(step.args[0]);
    } else if (step.name == "plugins") {
      need_args(step, 1);
      pm().loadPlugins(QDir(QString::fromStdString(step.args[0])));
      functions_.reset();
      std::cout << "plugins " << step.args[0] << ": " << pm().size() << " loaded\n";
    } else if (step.name == "version") {
      need_args(step, 0);
      version();
    } else if (step.name == "list") {
      need_args(step, 0);
      list();
    } else if (step.name == "load") {
      need_args(step, 1);
      load(step.args[0]);
    } else if (step.name == "filter") {
      need_args(step, 1);
      filter(step.args[0], step.options);
    } else if (step.name == "save") {
      need_args(step, 1);
      save(step.args[0], step.options);
    } else if (step.name == "layers") {
      std::cout << "layers: " << md_.meshNumber() << "\n";
      for (MeshModel& m : md_.meshIterator()) {
        std::cout << "layer " << m.id() << " '" << m.label().toStdString() << "' " << m.cm.vn << " "
                  << m.cm.fn << " " << m.cm.en << "\n";
      }
    }
  }

 private:
  static PluginManager& pm() { return meshlab::pluginManagerInstance(); }

  static void need_args(const Step& step, std::size_t n) {
    if (step.args.size() != n)
      usage("'" + step.name + "' takes " + std::to_string(n) + " argument(s)");
    if (!step.options.empty() && step.name != "filter" && step.name != "save")
      usage("'" + step.name + "' takes no key=value options");
  }

  //! pymeshlab's FunctionSet over the plugins loaded so far.
  const pymeshlab::FunctionSet& functions() {
    if (!functions_)
      functions_ = std::make_unique<pymeshlab::FunctionSet>(pm());
    return *functions_;
  }

  void load_plugin(const std::string& file) {
    MeshLabPlugin* plugin = pm().loadPlugin(QString::fromStdString(file));
    functions_.reset();
    std::cout << "plugin " << QFileInfo(QString::fromStdString(file)).fileName().toStdString()
              << ": " << plugin->pluginName().toStdString() << "\n";
  }

  void version() {
    std::cout << "meshlab-common version=" << meshlab::meshlabCompleteVersion() << "\n";
    for (MeshLabPlugin* p : pm().pluginIterator(true)) {
      const std::pair<std::string, bool> v = p->getMLVersion();
      std::cout << "plugin " << p->pluginFileInfo().fileName().toStdString()
                << " version=" << v.first << " precision=" << (v.second ? "double" : "float")
                << "\n";
    }
  }

  void list() {
    const pymeshlab::FunctionSet& fs = functions();
    for (const std::string& name : fs.pythonFilterFunctionNames()) {
      const pymeshlab::Function& f = fs.filterFunction(QString::fromStdString(name));
      std::cout << "filter " << name << " (" << f.meshlabFunctionName().toStdString() << ")\n";
      for (const pymeshlab::FunctionParameter& p : f) {
        std::cout << "  " << p.pythonName().toStdString() << " : "
                  << p.pythonTypeString().toStdString() << " = "
                  << p.defaultValueString().toStdString() << "\n";
      }
    }
  }

  void load(const std::string& file) {
    const QString path = QString::fromStdString(file);
    if (!QFileInfo::exists(path))
      throw MLException("File does not exist: " + path);
    const std::list<MeshModel*> meshes = meshlab::loadMeshWithStandardParameters(path, md_);
    print_new_log();
    for (MeshModel* m : meshes) {
      std::cout << "loaded " << file << ": layer " << m->id() << " '" << m->label().toStdString()
                << "' " << m->cm.vn << " vertices, " << m->cm.fn << " faces\n";
    }
  }

  //! The filter plugin and action whose MeshLab name is `meshlab_name`.
  static std::pair<FilterPlugin*, QAction*> find_action(const QString& meshlab_name) {
    for (FilterPlugin* fp : pm().filterPluginIterator()) {
      for (QAction* act : fp->actions()) {
        if (fp->filterName(act) == meshlab_name)
          return {fp, act};
      }
    }
    throw MLException("No loaded plugin has the filter " + meshlab_name);
  }

  void filter(const std::string& python_name,
              const std::vector<std::pair<std::string, std::string>>& options) {
    const QString name = QString::fromStdString(python_name);
    const pymeshlab::FunctionSet& fs = functions();
    if (!fs.containsFilterFunction(name))
      throw MLException("Failed to apply filter: " + name +
                        "\nFilter does not exist (see the runner's `list`).");
    if (md_.mm() == nullptr)
      throw MLException("Failed to apply filter: " + name + ": no mesh loaded");
    const auto [fp, action] = find_action(fs.filterFunction(name).meshlabFunctionName());

    RichParameterList params = fp->initParameterList(action, md_);
    for (const auto& [key, value] : options) {
      RichParameter* par = nullptr;
      for (RichParameter& p : params) {
        if (p.pythonName().toStdString() == key)
          par = &p;
      }
      if (par == nullptr)
        throw MLException("Parameter " + QString::fromStdString(key) + " not found for filter " +
                          name + ". Please check the documentation.");
      set_parameter(*par, value);
    }
    std::cout << "filter " << python_name << " (" << fp->filterName(action).toStdString()
              << ") on layer " << md_.mm()->id() << " '" << md_.mm()->label().toStdString() << "':";
    for (const RichParameter& p : params)
      std::cout << ' ' << p.pythonName().toStdString() << '=' << value_text(p);
    std::cout << "\n";

    QStringList missing;
    if (check_preconditions_ && !fp->isFilterApplicable(action, *md_.mm(), missing)) {
      throw MLException("Failed to apply filter: '" + name + "'. Current mesh does not have " +
                        missing.join(",") + ".");
    }
    fp->setLog(&md_.Log);
    md_.mm()->updateDataMask(fp->getRequirements(action));
    unsigned int post_condition = MeshModel::MM_UNKNOWN;
    std::map<std::string, QVariant> result;
    try {
      result = fp->applyFilter(action, params, md_, post_condition, nullptr);
    } catch (const std::exception& e) {
      print_new_log();
      fp->setLog(nullptr);
      throw MLException("Failed to apply filter: " + name + "\nDetails: " + e.what());
    }
    fp->setLog(nullptr);
    for (MeshModel& m : md_.meshIterator())
      vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
    if (md_.mm() != nullptr) {
      md_.mm()->cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(md_.mm()->cm));
      md_.mm()->cm.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(md_.mm()->cm));
    }
    print_new_log();
    for (const auto& [key, value] : result)
      std::cout << "result: " << key << '=' << result_text(value) << "\n";
  }

  static std::string value_text(const RichParameter& p) {
    const Value& v = p.value();
    if (v.isBool())
      return v.getBool() ? "True" : "False";
    if (v.isInt())
      return std::to_string(v.getInt());
    if (v.isFloat())
      return QString::number(double(v.getFloat())).toStdString();
    if (v.isString())
      return v.getString().toStdString();
    return "?";
  }

  MeshModel* layer(const std::string& which) {
    if (which == "current") {
      if (md_.mm() == nullptr)
        throw MLException("No current layer");
      return md_.mm();
    }
    MeshModel* found = nullptr;
    if (which == "last") {
      for (MeshModel& m : md_.meshIterator())
        found = &m;
    } else {
      bool ok = false;
      const int id = QString::fromStdString(which).toInt(&ok);
      if (ok)
        found = md_.getMesh(id);
    }
    if (found == nullptr)
      throw MLException("No layer '" + QString::fromStdString(which) + "'");
    return found;
  }

  void save(const std::string& file,
            const std::vector<std::pair<std::string, std::string>>& options) {
    std::string which = "current", attributes = "default", binary;
    for (const auto& [key, value] : options) {
      if (key == "layer")
        which = value;
      else if (key == "attributes")
        attributes = value;
      else if (key == "binary")
        binary = value;
      else
        usage("save: unknown option " + key);
    }
    MeshModel* m = layer(which);
    if (m->cm.vn == 0) {
      // MeshLab's exporters refuse an empty mesh ("Vertices not valid"); meshlabserver skipped it.
      std::cout << "not saved " << file << ": layer " << m->id() << " '" << m->label().toStdString()
                << "' is empty\n";
      return;
    }
    const QFileInfo info(QString::fromStdString(file));
    const QString ext = info.suffix().toLower();
    IOPlugin* io = pm().outputMeshPlugin(ext);
    if (io == nullptr)
      throw MLException("Unknown format for save: " + ext);

    int capability = 0, default_bits = 0;
    io->exportMaskCapability(ext, capability, default_bits);
    int mesh_capability = 0;  // what the layer has (pymeshlab's currentMeshIOCapabilityMask)
    for (int bit : pymeshlab::capabilitiesBits) {
      if (m->hasDataMask(MeshModel::io2mm(bit)))
        mesh_capability |= bit;
    }
    int mask = 0;
    if (attributes == "default") {
      mask = default_bits & (capability & mesh_capability);
    } else {
      static const std::map<std::string, int> kBits = {
          {"vc", vcg::tri::io::Mask::IOM_VERTCOLOR},
          {"vq", vcg::tri::io::Mask::IOM_VERTQUALITY},
          {"vf", vcg::tri::io::Mask::IOM_VERTFLAGS},
          {"vn", vcg::tri::io::Mask::IOM_VERTNORMAL},
          {"vt", vcg::tri::io::Mask::IOM_VERTTEXCOORD},
          {"fc", vcg::tri::io::Mask::IOM_FACECOLOR},
          {"fq", vcg::tri::io::Mask::IOM_FACEQUALITY},
          {"ff", vcg::tri::io::Mask::IOM_FACEFLAGS},
          {"fn", vcg::tri::io::Mask::IOM_FACENORMAL},
          {"wt", vcg::tri::io::Mask::IOM_WEDGTEXCOORD},
      };
      for (const QString& a : QString::fromStdString(attributes).split(',', Qt::SkipEmptyParts)) {
        const auto it = kBits.find(a.toStdString());
        if (it == kBits.end())
          usage("save: unknown attribute " + a.toStdString());
        mask |= it->second;
      }
      mask &= capability & mesh_capability;
    }
    // Edges are not among pymeshlab's capability bits; keep them whenever the format has them.
    mask |= capability & vcg::tri::io::Mask::IOM_EDGEINDEX;

    RichParameterList params = io->initSaveParameter(ext, *m);
    if (!binary.empty()) {
      if (!params.hasParameter("Binary"))
        usage("save: format " + ext.toStdString() + " has no binary option");
      params.setValue("Binary", BoolValue(parse_bool("binary", binary)));
    }
    io->setLog(&md_.Log);
    io->save(ext, info.absoluteFilePath(), *m, mask, params, nullptr);
    io->setLog(nullptr);
    print_new_log();
    std::cout << "saved " << file << ": layer " << m->id() << " '" << m->label().toStdString()
              << "' " << m->cm.vn << " vertices, " << m->cm.fn << " faces, " << m->cm.en
              << " edges\n";
  }

  //! MeshLab's log entries since the last call, one "log: " line per line of text.
  void print_new_log() {
    const auto& entries = md_.Log.logStringList();
    for (int i = logged_; i < entries.size(); ++i) {
      for (const QString& line : entries[i].second.split('\n'))
        std::cout << "log: " << line.toStdString() << "\n";
    }
    logged_ = entries.size();
  }

  bool check_preconditions_;
  MeshDocument md_;
  std::unique_ptr<pymeshlab::FunctionSet> functions_;  //!< over the plugins loaded so far
  int logged_ = 0;
};

//! pymeshlab's QDebugRedirect: MeshLab's qDebug chatter (GLLogStream echoes every log line) is
//! dropped; warnings and errors still go to stderr.
void drop_debug_messages(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtDebugMsg || type == QtInfoMsg)
    return;
  std::cerr << message.toStdString() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  // A QApplication, not a QCoreApplication: filter plugins give their actions keyboard shortcuts,
  // which need the GUI's shortcut map. No display: the offscreen platform unless told otherwise.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  qInstallMessageHandler(drop_debug_messages);
  QApplication app(argc, argv);
  std::vector<std::string> words(argv + 1, argv + argc);
  bool check_preconditions = true;
  if (!words.empty() && words.front() == "--no-precondition-check") {
    check_preconditions = false;
    words.erase(words.begin());
  }
  std::vector<Step> steps;
  for (const std::string& w : words) {
    if (is_step(w)) {
      steps.push_back({w, {}, {}});
    } else if (steps.empty()) {
      usage("expected a step, got '" + w + "'");
    } else if (const auto eq = w.find('=');
               eq != std::string::npos && eq > 0 &&
               (steps.back().name == "filter" || steps.back().name == "save") &&
               !steps.back().args.empty()) {
      steps.back().options.emplace_back(w.substr(0, eq), w.substr(eq + 1));
    } else {
      steps.back().args.push_back(w);
    }
  }
  if (steps.empty())
    usage("no steps");
  Runner runner(check_preconditions);
  try {
    for (const Step& step : steps)
      runner.run(step);
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
