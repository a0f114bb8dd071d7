// The product's `lexel` commands (run, sweep, merge, methods, mesh-info, info; the studies' are in
// cases/studies/<name>/): each loads its input, calls its runner (cases/run/), prints with its
// formatter (cases/report/) and writes its files. Flags live in main.cpp only; these take the
// parsed values. Each returns the exit status and throws InputError (exit 2) for bad input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {

// Where the shipped cases and the published tables live: cases/flatland, cases/spatial,
// cases/published under this directory.
std::filesystem::path DataDirectory();

// The method names with one line each, for --help: the flatland methods, the 3D methods, or both.
std::string MethodsHelp(bool flatland, bool spatial);

struct RunFlags {
    std::vector<std::string> cases;    // case files
    std::vector<std::string> methods;  // empty: all
    std::string metric = "l1";         // flatland only
    bool metricGiven = false;
    std::string format = "table";  // table | json | csv
    std::string outDir;            // empty: print only
    bool mapTruth = true;          // 3D: also the report's 4000² truth map
    int cascades = 0;              // 3D: partitions of the partitioned methods; 0: the case's
    int phases = 0;                // 3D: sub-texel phases errors are averaged over; 0: the case's
    int maxPhases = 0;             // 3D: the most a light's mean is raised to; 0: the case's
    std::string backend = "cpu";   // 3D: cpu | gl
};
int RunCommand(const RunFlags& flags);

struct SweepFlags {
    std::string casePath;
    int lights = 0;                    // 0: the case's light_sweep count
    std::string lightType;             // point | directional; empty: the case's
    std::vector<std::string> methods;  // empty: all
    std::string format = "table";      // table | markdown | csv | json
    std::string outDir;
    int cascades = 0;             // partitions of the partitioned methods; 0: the case's
    int phases = 0;               // sub-texel phases errors are averaged over; 0: the case's
    int maxPhases = 0;            // the most a light's mean is raised to; 0: the case's
    int shimmerPoses = 0;         // camera_path poses each light's shimmer is over; 0: none
    std::string backend = "cpu";  // cpu | gl
    std::string shard = "0/1";    // K/N: the lights i with i mod N = K
    bool resume = false;          // continue from the journal of a killed run into outDir
};
int SweepCommand(const SweepFlags& flags);

// `lexel merge DIR... --out DIR`: the shards' records (sweep-record.json) joined into the files
// of one whole sweep, the same bit for bit as an unsharded run's but for the times.
struct MergeFlags {
    std::vector<std::string> dirs;
    std::string outDir;
    std::string format = "table";  // table | markdown | csv | json
};
int MergeCommand(const MergeFlags& flags);

// A mesh file as lexel reads it: format, vertices, triangles and bounds in the file's units; with
// a 3D case, for each of its geometry entries that loads the file, the entry's up axis and units
// and the bounds after them (scene axes and units) and after the entry's transform (world).
// Without a case the up axis printed is the default, y. Bad input (a mesh lexel refuses, a case
// without an entry for the file) throws InputError or DomainError, nothing printed.
int MeshInfoCommand(const std::string& meshPath, const std::string& casePath);

// The version and the backends this build and machine offer (the GL renderer, or why none).
int InfoCommand(const std::string& version);
// Every method lexel knows (MethodListingText, or MethodListingJson when `json`) on stdout.
int MethodsCommand(bool json);

}  // namespace lexel::cases
