// monoplane's side of the OpenXR core validation layer (app/headset/xr_validation.h): with
// --validation the layer is enabled and its messages reach monoplane's count, so a misuse fails
// the command; without the layer installed, --validation refuses to run rather than pretend.
#include "app/headset/xr_validation.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace monoplane::headset {
namespace {

namespace fs = std::filesystem;

class XrValidationTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("xr_validation_" + std::to_string(getpid()));
        fs::create_directories(dir_);
        std::ofstream(dir_ / "script.toml") << "";
        setenv("XR_RUNTIME_JSON", SIMXR_MANIFEST, 1);
        setenv("SIMXR_SCRIPT", (dir_ / "script.toml").c_str(), 1);
    }
    void TearDown() override {
        unsetenv("XR_API_LAYER_PATH");
        fs::remove_all(dir_);
    }

    // An instance made the way OpenXrHeadset::create makes it.
    XrInstance create_instance(const XrValidation& validation) {
        XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
        std::strcpy(info.applicationInfo.applicationName, "xr_validation_test");
        info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
        info.enabledApiLayerCount = static_cast<std::uint32_t>(validation.layers().size());
        info.enabledApiLayerNames = validation.layers().data();
        info.enabledExtensionCount = static_cast<std::uint32_t>(validation.extensions().size());
        info.enabledExtensionNames = validation.extensions().data();
        XrInstance instance = XR_NULL_HANDLE;
        EXPECT_EQ(xrCreateInstance(&info, &instance), XR_SUCCESS);
        return instance;
    }

    fs::path dir_;
};

TEST_F(XrValidationTest, WithoutTheFlagNothingIsEnabled) {
    Result<XrValidation> planned = XrValidation::plan(false);
    ASSERT_TRUE(planned);
    EXPECT_FALSE(planned->enabled());
    EXPECT_TRUE(planned->layers().empty());
    EXPECT_TRUE(planned->extensions().empty());
}

TEST_F(XrValidationTest, CleanCallsLeaveNoMessageAndAMisuseIsCounted) {
    Result<XrValidation> planned = XrValidation::plan(true);
    ASSERT_TRUE(planned) << planned.error().message;
    XrValidation validation = std::move(planned.value());
    ASSERT_EQ(validation.layers().size(), 1u);
    EXPECT_STREQ(validation.layers()[0], kXrValidationLayer);
    const XrInstance instance = create_instance(validation);
    ASSERT_NE(instance, XR_NULL_HANDLE);
    ASSERT_TRUE(validation.attach(instance));

    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    EXPECT_EQ(xrGetSystem(instance, &system_info, &system), XR_SUCCESS);
    EXPECT_EQ(validation.messages().count(), 0u);

    // An enum value no XrFormFactor has: the layer must report it (VUID ...-formFactor-parameter).
    system_info.formFactor = static_cast<XrFormFactor>(77);
    EXPECT_EQ(xrGetSystem(instance, &system_info, &system), XR_ERROR_VALIDATION_FAILURE);
    ASSERT_GE(validation.messages().count(), 1u);
    const std::vector<std::string> first = validation.messages().first_messages();
    ASSERT_FALSE(first.empty());
    EXPECT_NE(first[0].find("VUID-XrSystemGetInfo-formFactor-parameter"), std::string::npos)
        << first[0];
    EXPECT_NE(first[0].find("xrGetSystem"), std::string::npos) << first[0];

    validation.detach();
    EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);
}

// The layer already enabled through the loader's environment variable (as the OpenXR docs
// suggest for any application): naming it again made Debian 12's loader refuse the instance
// (XR_ERROR_API_LAYER_NOT_PRESENT); now it is not named again, and its messages still arrive.
TEST_F(XrValidationTest, ALayerTheEnvironmentEnablesIsNotNamedTwice) {
    setenv("XR_ENABLE_API_LAYERS", (std::string("XR_APILAYER_other:") + kXrValidationLayer).c_str(),
           1);
    Result<XrValidation> planned = XrValidation::plan(true);
    ASSERT_TRUE(planned) << planned.error().message;
    XrValidation validation = std::move(planned.value());
    EXPECT_TRUE(validation.enabled());
    EXPECT_TRUE(validation.layers().empty());
    // The loader warns about the unknown XR_APILAYER_other but creates the instance.
    setenv("XR_ENABLE_API_LAYERS", kXrValidationLayer, 1);
    const XrInstance instance = create_instance(validation);
    unsetenv("XR_ENABLE_API_LAYERS");
    ASSERT_NE(instance, XR_NULL_HANDLE);
    ASSERT_TRUE(validation.attach(instance));
    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = static_cast<XrFormFactor>(77);
    XrSystemId system = XR_NULL_SYSTEM_ID;
    EXPECT_EQ(xrGetSystem(instance, &system_info, &system), XR_ERROR_VALIDATION_FAILURE);
    EXPECT_GE(validation.messages().count(), 1u);
    validation.detach();
    EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);
}

TEST_F(XrValidationTest, AMissingLayerIsRefusedWithWhatToInstall) {
    // The loader looks for explicit layers only here now: an empty folder.
    setenv("XR_API_LAYER_PATH", dir_.c_str(), 1);
    Result<XrValidation> planned = XrValidation::plan(true);
    ASSERT_FALSE(planned);
    EXPECT_NE(planned.error().message.find("openxr-layer-corevalidation"), std::string::npos)
        << planned.error().message;
}

}  // namespace
}  // namespace monoplane::headset
