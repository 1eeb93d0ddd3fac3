# Every dependency comes from Debian 12 packages (scripts/install-deps.sh); nothing is downloaded.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)
find_package(ompl 1.5 REQUIRED)  # config file is omplConfig.cmake (lower case)
find_package(fcl 0.7 REQUIRED)
find_package(urdfdom REQUIRED)
find_package(tinyxml2 REQUIRED)
find_package(assimp REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Bullet REQUIRED)  # CMake's FindBullet module (float build)
find_package(Threads REQUIRED)
# Orocos KDL + kdl_parser: only `ropras bench-ik` and the tests use them (the comparison with our IK); no library
# links them and no public header includes them. kdl_parser's CMake config is catkin's and pulls in ROS/ament
# modules, so its header and library are found directly.
find_package(orocos_kdl 1.4 REQUIRED)
find_path(ROPRAS_KDL_PARSER_INCLUDE_DIR kdl_parser/kdl_parser.hpp REQUIRED)
find_library(ROPRAS_KDL_PARSER_LIBRARY kdl_parser REQUIRED)

# OMPL 1.5 defines variables only; link libompl.so alone (its list names boost libraries we do not need).
list(GET OMPL_LIBRARIES 0 ROPRAS_OMPL_CORE_LIB)
add_library(ropras_ompl_iface INTERFACE)
target_include_directories(ropras_ompl_iface SYSTEM INTERFACE ${OMPL_INCLUDE_DIRS})
target_link_libraries(ropras_ompl_iface INTERFACE ${ROPRAS_OMPL_CORE_LIB} Boost::headers Eigen3::Eigen)
set_target_properties(ropras_ompl_iface PROPERTIES EXPORT_NAME ompl_iface)
install(TARGETS ropras_ompl_iface EXPORT roprasTargets)

add_library(ropras_bullet_iface INTERFACE)
target_include_directories(ropras_bullet_iface SYSTEM INTERFACE ${BULLET_INCLUDE_DIRS})
target_link_libraries(ropras_bullet_iface INTERFACE ${BULLET_LIBRARIES})
set_target_properties(ropras_bullet_iface PROPERTIES EXPORT_NAME bullet_iface)
install(TARGETS ropras_bullet_iface EXPORT roprasTargets)

add_library(ropras_kdl_iface INTERFACE)
target_include_directories(ropras_kdl_iface SYSTEM INTERFACE ${orocos_kdl_INCLUDE_DIRS} ${ROPRAS_KDL_PARSER_INCLUDE_DIR})
target_link_libraries(ropras_kdl_iface INTERFACE ${ROPRAS_KDL_PARSER_LIBRARY} ${orocos_kdl_LIBRARIES} Eigen3::Eigen)
