// LeakSanitizer suppressions for the libraries live capture and ROS load: ALSA keeps its parsed
// configuration for the life of the process, PortAudio's host APIs and roscpp's singletons
// (log4cxx, XML-RPC, boost threads) are freed by nobody at exit. These are not echoplan's
// allocations; a leak in echoplan's own code is still reported. Linked into the executables that
// use PortAudio or roscpp in the sanitizer build only (src/robot/CMakeLists.txt).
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libasound.so\n"
         "leak:libportaudio.so\n"
         "leak:libjack.so\n"
         "leak:libroscpp.so\n"
         "leak:librosconsole\n"
         "leak:liblog4cxx.so\n"
         "leak:libxmlrpcpp.so\n"
         "leak:libboost_\n"
         "leak:libapr-1.so\n"
         "leak:libclass_loader.so\n"
         "leak:librosbag_storage.so\n";
}
